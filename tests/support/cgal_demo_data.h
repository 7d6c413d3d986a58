// Real models from Debian's libcgal-demo, fetched by scripts/get-cgal-data.sh into data/cgal-demo/
// (never committed). A test asking for one that is absent fails, naming the command that fetches
// it, unless the environment sets DELPSC_ALLOW_MISSING_CGAL_DATA (to anything but empty): then it
// only says so and the caller skips the model. Without that rule a run whose download failed
// passed every real-model check unseen.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <delpsc/io/triangle_soup.h>

namespace delpsc::test {

/// data/cgal-demo/NAME.off, or nothing when it is absent (reported as above).
std::optional<std::filesystem::path> cgal_demo_file(const std::string& name);

/// The model read from cgal_demo_file(name), or nothing when it is absent.
std::optional<io::TriangleSoup> cgal_demo_soup(const std::string& name);

}  // namespace delpsc::test
