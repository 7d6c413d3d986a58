#include "cgal_demo_data.h"

#include <cstdlib>

#include <doctest/doctest.h>

#include <delpsc/io/read_model.h>

namespace delpsc::test {

std::optional<std::filesystem::path> cgal_demo_file(const std::string& name) {
  // This file is tests/support/cgal_demo_data.cpp; the data sit in data/cgal-demo/ at the root.
  const auto path = std::filesystem::path(__FILE__).parent_path() / "../../data/cgal-demo" / (name + ".off");
  if (std::filesystem::exists(path)) return path;
  const char* allow = std::getenv("DELPSC_ALLOW_MISSING_CGAL_DATA");
  if (allow != nullptr && *allow != '\0')
    MESSAGE(name << ".off absent from data/cgal-demo (DELPSC_ALLOW_MISSING_CGAL_DATA is set): not tested on it");
  else
    FAIL_CHECK(name << ".off absent from data/cgal-demo: run scripts/get-cgal-data.sh, or set "
                       "DELPSC_ALLOW_MISSING_CGAL_DATA=1 to skip the real models");
  return std::nullopt;
}

std::optional<io::TriangleSoup> cgal_demo_soup(const std::string& name) {
  const auto path = cgal_demo_file(name);
  if (!path) return std::nullopt;
  return io::read_model(path->string()).soup;
}

}  // namespace delpsc::test
