// The STEP reader as a module (forces/geometry/step_module.hpp): a process linked to
// yardsim::forces only (no OCCT) has no OpenCASCADE library mapped until it reads a STEP file;
// reading one loads the module from beside libyardsim_forces.so and gives the box's closed-form
// volume; a missing module or one without the entry is refused naming the file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/primitive_meshes.hpp"
#include "forces/geometry/step_module.hpp"
#include "forces/geometry/step_reader.hpp"
#include "support/test_paths.hpp"

using namespace yardsim::forces;
using Catch::Matchers::Contains;

namespace {

// () => whether a library of OpenCASCADE's kernel (libTKernel) is mapped in this process
bool occtMapped() {
  std::ifstream maps("/proc/self/maps");
  std::stringstream text;
  text << maps.rdbuf();
  return text.str().find("libTKernel") != std::string::npos;
}

const std::string kBox = std::string(YARDSIM_SOURCE_DIR) + "/examples/yard/box_2x3x4.step";

}  // namespace

TEST_CASE("OpenCASCADE is mapped only once a STEP file is read", "[step]") {
  REQUIRE(stepSupported());
  REQUIRE_FALSE(occtMapped());
  // other meshes and a refused STEP path do not load it
  const TriangleMesh box = boxMesh(yardsim::dynamics::Vector3(2.0, 3.0, 4.0));
  CHECK(solidProperties(box).volume == Approx(24.0));
  CHECK_THROWS_WITH(readStep("/nonexistent/none.step"), Contains("cannot open"));
  CHECK_FALSE(occtMapped());
  // the 2 x 3 x 4 m box written in millimetres by OCCT: its B-rep volume and centre
  const StepModel m = readStep(kBox);
  CHECK(occtMapped());
  CHECK(m.solids == 1);
  CHECK(m.brep.volume == Approx(24.0).epsilon(1e-9));
  CHECK(m.brep.centroid.x() == Approx(1.0).epsilon(1e-9));
  CHECK(m.brep.centroid.y() == Approx(1.5).epsilon(1e-9));
  CHECK(m.brep.centroid.z() == Approx(2.0).epsilon(1e-9));
  CHECK(solidProperties(m.mesh).volume == Approx(24.0).epsilon(1e-9));
  CHECK(readMesh(kBox).triangles.size() == m.mesh.triangles.size());
}

TEST_CASE("The STEP module sits beside libyardsim_forces and a missing one is named", "[step]") {
  const std::filesystem::path module = stepModulePath();
  CHECK(module.filename() == "libyardsim_step.so");
  CHECK(std::filesystem::is_regular_file(module));
  CHECK(std::filesystem::is_regular_file(module.parent_path() / "libyardsim_forces.so"));
  CHECK_THROWS_WITH(loadStepModule("/nonexistent/libyardsim_step.so"),
                    Contains("/nonexistent/libyardsim_step.so") && Contains("missing") &&
                        Contains("YARDSIM_WITH_STEP=ON"));
  // a loadable library without the entry
  const std::string forces = (module.parent_path() / "libyardsim_forces.so").string();
  CHECK_THROWS_WITH(loadStepModule(forces), Contains(forces) && Contains("yardsim_step_read"));
  // a file that is no library
  CHECK_THROWS_WITH(loadStepModule(kBox), Contains(kBox) && Contains("cannot be loaded"));
}
