// The coordinates a command prints and writes: those of the model's file. load_model
// (model_input.h) moves a model lying far from the origin next to it before anything is computed
// (io/model_frame.h); what it subtracted is kept here and added back on the way out.
#pragma once

#include <span>

#include <delpsc/io/model_frame.h>
#include <delpsc/kernel/point.h>

namespace delpsc::app {

/// What load_model subtracted from the model's coordinates (zero for a model near the origin). A
/// command reads one model, so one value per process.
inline Vec3& model_offset() {
  static Vec3 offset = Vec3::Zero();
  return offset;
}

/// A point of the moved model in the file's coordinates, for messages.
inline Vec3 in_file_frame(const Vec3& p) { return p + model_offset(); }

/// Points of the moved model back in the file's coordinates, for an output file. O(n).
inline void move_to_file_frame(std::span<Vec3> points) { io::move_by(points, model_offset()); }

}  // namespace delpsc::app
