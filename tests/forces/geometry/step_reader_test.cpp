// STEP files written here by OpenCASCADE itself (a box, a cylinder, an open-topped hollow block,
// a two-part assembly, a file in millimetres), read back by readStep: the B-rep's volume, centre
// and inertia against closed forms, the mesh closed and its own properties within the bound the
// chord tolerance sets (|dV| <= surface area x chord); broken, empty and solid-less files refused.
#include <catch2/catch.hpp>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "forces/geometry/mesh_io.hpp"
#include "forces/geometry/step_reader.hpp"
#include "support/scene_files.hpp"

using namespace yardsim::forces;
using Catch::Matchers::Contains;
using yardsim::dynamics::Matrix3;
using yardsim::dynamics::Vector3;
using yardsim::testing::SceneDir;

namespace {

// (shape, path, unit the file states) => a STEP AP214 file; assemblies kept as assemblies
void writeStep(const TopoDS_Shape& shape, const std::string& path, const char* unit = "M") {
  STEPControl_Controller::Init();
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  Interface_Static::SetCVal("write.step.unit", unit);
  Interface_Static::SetIVal("write.step.assembly", 1);
  STEPControl_Writer writer;
  REQUIRE(writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone);
  REQUIRE(writer.Write(path.c_str()) == IFSelect_RetDone);
}

// (corner, size) => an axis-aligned box solid
TopoDS_Shape box(const Vector3& corner, const Vector3& size) {
  return BRepPrimAPI_MakeBox(gp_Pnt(corner.x(), corner.y(), corner.z()), size.x(), size.y(),
                             size.z())
      .Shape();
}

// (size, density 1) => the inertia of a box about its centre, m^5
Matrix3 boxInertia(const Vector3& s) {
  const double V = s.prod();
  return (V / 12.0 *
          Vector3(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                  s.x() * s.x() + s.y() * s.y()))
      .asDiagonal();
}

// (model, surface area) => the mesh's own properties agree with the B-rep's within the bounds
// the chord sets: the solids differ by at most dV = area x chord, every point of it within R
// (the farthest vertex) of the centroid, so the first moment moves by <= 2 R dV and each
// second moment by <= 2 R^2 dV
void checkMeshAgainstBrep(const StepModel& m, double area) {
  const SolidProperties mesh = solidProperties(m.mesh);
  const double dV = area * m.tolerance.chord, V = m.brep.volume;
  double R = 0;
  for (const auto& v : m.mesh.vertices) R = std::max(R, (v - m.brep.centroid).norm());
  CHECK(std::abs(mesh.volume - V) <= dV);
  CHECK((mesh.centroid - m.brep.centroid).norm() <= 2 * R * dV / (V - dV));
  CHECK((mesh.inertia - m.brep.inertia).cwiseAbs().maxCoeff() <= 2 * R * R * dV);
}

}  // namespace

TEST_CASE("a STEP box reads back in metres with its closed-form volume, centre and inertia") {
  SceneDir dir;
  const Vector3 corner(1.0, -2.0, 0.5), size(4.0, 3.0, 2.0);
  writeStep(box(corner, size), dir.file("box.step"));
  writeStep(box(corner, size), dir.file("box_mm.stp"), "MM");  // the file states millimetres
  for (const char* name : {"box.step", "box_mm.stp"}) {
    INFO(name);
    const StepModel m = readStep(dir.file(name));
    CHECK(m.solids == 1);
    CHECK(m.mesh.triangles.size() == 12);  // six planar faces, two triangles each
    CHECK(m.mesh.vertices.size() == 8);    // corners welded across faces
    CHECK(m.brep.volume == Approx(24.0).epsilon(1e-9));
    CHECK((m.brep.centroid - (corner + size / 2)).norm() < 1e-9);
    CHECK((m.brep.inertia - boxInertia(size)).norm() < 1e-8);
    const SolidProperties mesh = solidProperties(m.mesh);  // planar: the mesh is exact
    CHECK(mesh.volume == Approx(24.0).epsilon(1e-12));
    CHECK((mesh.inertia - boxInertia(size)).norm() < 1e-9);
  }
  // readMesh dispatches on the extension, as scenes' geometry: {mesh: ...} uses it
  CHECK(readClosedMesh(dir.file("box.step")).triangles.size() == 12);
}

TEST_CASE("a STEP box turned about two axes: B-rep and mesh inertia agree off the diagonal") {
  SceneDir dir;
  gp_Trsf turn;
  turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 1, 0.5)), 0.7);
  writeStep(box(Vector3(0, 0, 0), Vector3(5, 2, 1)).Moved(TopLoc_Location(turn)),
            dir.file("turned.step"));
  const StepModel m = readStep(dir.file("turned.step"));
  const SolidProperties mesh = solidProperties(m.mesh);
  CHECK(std::abs(m.brep.inertia(0, 1)) > 1.0);  // a real product of inertia to compare
  CHECK((mesh.inertia - m.brep.inertia).norm() < 1e-9 * m.brep.inertia.norm());
  CHECK((mesh.centroid - m.brep.centroid).norm() < 1e-12 * 5);
  // eigenvalues: the box's principal moments whatever the turn
  Eigen::SelfAdjointEigenSolver<Matrix3> eig(m.brep.inertia);
  const Vector3 principal = boxInertia(Vector3(5, 2, 1)).diagonal();
  Vector3 sorted = principal;
  std::sort(sorted.data(), sorted.data() + 3);
  CHECK((eig.eigenvalues() - sorted).norm() < 1e-8);
}

TEST_CASE(
    "a STEP cylinder: closed forms, and a finer chord gives more triangles and a closer mesh") {
  SceneDir dir;
  const double r = 1.5, h = 4.0;
  writeStep(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -1), gp_Dir(0, 0, 1)), r, h).Shape(),
            dir.file("cyl.step"));
  const double V = M_PI * r * r * h, area = 2 * M_PI * r * (r + h);
  std::size_t previous = 0;
  double previousError = 1e9;
  for (double chord : {1e-2, 1e-3, 1e-4}) {
    INFO("chord " << chord);
    const StepModel m = readStep(dir.file("cyl.step"), {chord, 0.5});
    CHECK(m.brep.volume == Approx(V).epsilon(1e-9));
    CHECK((m.brep.centroid - Vector3(0, 0, 1)).norm() < 1e-9);
    CHECK(m.brep.inertia(0, 0) == Approx(V * (3 * r * r + h * h) / 12).epsilon(1e-9));
    CHECK(m.brep.inertia(1, 1) == Approx(V * (3 * r * r + h * h) / 12).epsilon(1e-9));
    CHECK(m.brep.inertia(2, 2) == Approx(V * r * r / 2).epsilon(1e-9));
    checkMeshAgainstBrep(m, area);
    const double error = std::abs(solidProperties(m.mesh).volume - V);
    CHECK(m.mesh.triangles.size() > previous);
    CHECK(error < previousError);
    previous = m.mesh.triangles.size();
    previousError = error;
  }
}

TEST_CASE("a hollow STEP block open at the top: one closed surface, composite closed forms") {
  SceneDir dir;
  // outer 4 x 3 x 2, a pocket 3.6 x 2.6 from z = 0.2 through the top: walls 0.2, floor 0.2
  const Vector3 outer(4, 3, 2), pocket(3.6, 2.6, 2.0), pocketCorner(0.2, 0.2, 0.2);
  BRepAlgoAPI_Cut cut(box(Vector3::Zero(), outer), box(pocketCorner, pocket));
  REQUIRE(cut.IsDone());
  writeStep(cut.Shape(), dir.file("hollow.step"));
  const StepModel m = readStep(dir.file("hollow.step"));
  // the part of the pocket inside the block is 3.6 x 2.6 x 1.8
  const Vector3 inside(3.6, 2.6, 1.8), insideCentre = pocketCorner + inside / 2;
  const double Vo = outer.prod(), Vi = inside.prod(), V = Vo - Vi;
  const Vector3 c = (Vo * outer / 2 - Vi * insideCentre) / V;
  // (box of size s and centre p) => its inertia about c, parallel axes
  auto about = [&](const Vector3& s, const Vector3& p) {
    const Vector3 d = p - c;
    return Matrix3(boxInertia(s) +
                   s.prod() * (d.squaredNorm() * Matrix3::Identity() - d * d.transpose()));
  };
  const Matrix3 I = about(outer, outer / 2) - about(inside, insideCentre);
  CHECK(m.solids == 1);
  CHECK(m.brep.volume == Approx(V).epsilon(1e-9));
  CHECK((m.brep.centroid - c).norm() < 1e-9);
  CHECK((m.brep.inertia - I).norm() < 1e-8 * I.norm());
  const SolidProperties mesh = solidProperties(m.mesh);
  CHECK(mesh.volume == Approx(V).epsilon(1e-12));
  CHECK((mesh.inertia - I).norm() < 1e-9 * I.norm());
}

TEST_CASE("a two-part STEP assembly is flattened with each part's placement") {
  SceneDir dir;
  // one unit-cube part instanced twice: at the origin and moved 3 m along x and turned
  const TopoDS_Shape part = box(Vector3::Zero(), Vector3(1, 1, 1));
  gp_Trsf place;
  place.SetRotation(gp_Ax1(gp_Pnt(0.5, 0.5, 0.5), gp_Dir(0, 0, 1)), M_PI / 2);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(3, 0, 0));
  TopoDS_Compound assembly;
  BRep_Builder builder;
  builder.MakeCompound(assembly);
  builder.Add(assembly, part);
  builder.Add(assembly, part.Moved(TopLoc_Location(shift * place)));
  writeStep(assembly, dir.file("pair.step"));
  const StepModel m = readStep(dir.file("pair.step"));
  CHECK(m.solids == 2);
  CHECK(m.mesh.triangles.size() == 24);
  CHECK(m.brep.volume == Approx(2.0).epsilon(1e-9));
  CHECK((m.brep.centroid - Vector3(2.0, 0.5, 0.5)).norm() < 1e-9);
  // each cube 1/6 about its centre; the centres 1.5 m either side of the middle along x
  CHECK(m.brep.inertia(0, 0) == Approx(2.0 / 6).epsilon(1e-9));
  CHECK(m.brep.inertia(1, 1) == Approx(2.0 / 6 + 2 * 2.25).epsilon(1e-9));
  CHECK(m.brep.inertia(2, 2) == Approx(2.0 / 6 + 2 * 2.25).epsilon(1e-9));
  const SolidProperties mesh = solidProperties(m.mesh);
  CHECK(mesh.volume == Approx(2.0).epsilon(1e-12));
  CHECK((mesh.centroid - Vector3(2.0, 0.5, 0.5)).norm() < 1e-12);
}

TEST_CASE("broken, empty, solid-less and missing STEP files are refused naming the file") {
  SceneDir dir;
  dir.write("empty.step", "");
  dir.write("broken.step", "ISO-10303-21;\nHEADER;\nthis is not STEP\n");
  CHECK_THROWS_WITH(readStep(dir.file("empty.step")),
                    Contains("empty.step") && Contains("not a readable STEP"));
  CHECK_THROWS_WITH(readStep(dir.file("broken.step")), Contains("broken.step"));
  CHECK_THROWS_WITH(readStep(dir.file("none.step")), Contains("cannot open"));
  // a single planar face: a surface, no solid
  writeStep(BRepBuilderAPI_MakeFace(
                BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0), gp_Pnt(1, 1, 0), true)
                    .Wire())
                .Face(),
            dir.file("face.step"));
  CHECK_THROWS_WITH(readStep(dir.file("face.step")), Contains("no solid"));
  CHECK_THROWS_WITH(readStep(dir.file("face.step"), {0.0, 0.5}), Contains("must be > 0"));
  CHECK(stepSupported());
}
