// The STEP reader's OpenCASCADE half: built as the module libyardsim_step.so beside
// libyardsim_forces.so and loaded by readStep (step_reader.cpp) only when a scene reads a STEP
// file, so a run without one never maps OCCT (docs/performance.md). A build without shared
// libraries links this file into yardsim_forces instead. Units: lengths in metres.
#include "forces/geometry/step_module.hpp"

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

#include <cmath>
#include <unordered_map>
#include <vector>

namespace yardsim::forces {

using dynamics::Matrix3;
using dynamics::Vector3;

namespace {

// Merges vertices closer than a tolerance (a grid of cells of that size, searched 3x3x3).
class Welder {
 public:
  explicit Welder(double tolerance) : tol_(tolerance) {}
  // (point) => the index of an existing vertex within the tolerance, or of the point added
  int add(const Vector3& p, std::vector<Vector3>& vertices) {
    const long long cx = cell(p.x()), cy = cell(p.y()), cz = cell(p.z());
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto range = cells_.equal_range(key(cx + dx, cy + dy, cz + dz));
          for (auto it = range.first; it != range.second; ++it)
            if ((vertices[static_cast<std::size_t>(it->second)] - p).norm() <= tol_)
              return it->second;
        }
    const int index = static_cast<int>(vertices.size());
    vertices.push_back(p);
    cells_.emplace(key(cx, cy, cz), index);
    return index;
  }

 private:
  long long cell(double x) const { return static_cast<long long>(std::floor(x / tol_)); }
  static std::size_t key(long long x, long long y, long long z) {
    return static_cast<std::size_t>(x * 73856093LL ^ y * 19349663LL ^ z * 83492791LL);
  }
  double tol_;
  std::unordered_multimap<std::size_t, int> cells_;
};

// (solid, weld tolerance, mesh) => the solid's face triangulations appended to the mesh, placed
// by their locations, reversed faces turned, corners welded within the solid
void appendSolid(const TopoDS_Shape& solid, double weldTolerance, TriangleMesh& mesh) {
  Welder welder(weldTolerance);
  for (TopExp_Explorer ex(solid, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, location);
    if (tri.IsNull()) throw MeshError(mesh.source + ": a face of a solid could not be tessellated");
    const gp_Trsf placement = location.Transformation();
    std::vector<int> index(static_cast<std::size_t>(tri->NbNodes()) + 1);
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      const gp_Pnt p = tri->Node(i).Transformed(placement);
      index[static_cast<std::size_t>(i)] = welder.add(Vector3(p.X(), p.Y(), p.Z()), mesh.vertices);
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a = 0, b = 0, c = 0;
      tri->Triangle(i).Get(a, b, c);
      if (reversed) std::swap(b, c);
      const std::array<int, 3> t{index[static_cast<std::size_t>(a)],
                                 index[static_cast<std::size_t>(b)],
                                 index[static_cast<std::size_t>(c)]};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // collapsed at a pole or apex
      mesh.triangles.push_back(t);
    }
  }
}

// (path, tolerance) => the STEP file's solids meshed and their B-rep properties (readStep's
// contract; the path and tolerances already checked by it, the mesh's closedness checked after)
StepModel readStepOcct(const std::string& path, const StepTolerance& tolerance) {
  StepModel model;
  model.mesh.source = path;
  model.tolerance = tolerance;
  try {
    // (file) => its shapes in metres: the session unit set before the transfer
    STEPControl_Controller::Init();
    // (OCCT's own console messages) => silenced: the error we throw says what went wrong
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    Interface_Static::SetCVal("xstep.cascade.unit", "M");
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw MeshError(path + ": not a readable STEP file (ISO 10303-21)");
    if (reader.TransferRoots() == 0) throw MeshError(path + ": the STEP file holds no shape");
    const TopoDS_Shape shape = reader.OneShape();
    // (assembly) => its solids, each with its placement composed, in one compound
    TopoDS_Compound solids;
    BRep_Builder builder;
    builder.MakeCompound(solids);
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) {
      builder.Add(solids, ex.Current());
      ++model.solids;
    }
    if (model.solids == 0)
      throw MeshError(path +
                      ": the STEP file holds no solid (only surfaces, curves or nothing); "
                      "export closed solids from the CAD system");
    BRepMesh_IncrementalMesh mesher(solids, tolerance.chord, false, tolerance.angle, false);
    if (!mesher.IsDone()) throw MeshError(path + ": the tessellation failed");
    Bnd_Box box;
    BRepBndLib::Add(solids, box);
    const double diagonal = std::sqrt(box.SquareExtent());
    for (TopExp_Explorer ex(solids, TopAbs_SOLID); ex.More(); ex.Next())
      appendSolid(ex.Current(), 1e-9 * std::max(diagonal, 1.0), model.mesh);
    // (B-rep) => exact volume, centre and inertia about the centre at unit density
    GProp_GProps props;
    BRepGProp::VolumeProperties(solids, props);
    model.brep.volume = props.Mass();
    const gp_Pnt g = props.CentreOfMass();
    model.brep.centroid = Vector3(g.X(), g.Y(), g.Z());
    const gp_Mat I = props.MatrixOfInertia();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) model.brep.inertia(i, j) = I.Value(i + 1, j + 1);
  } catch (const Standard_Failure& e) {
    throw MeshError(path + ": OpenCASCADE failed reading the STEP file: " + e.GetMessageString());
  }
  if (!(model.brep.volume > 0))
    throw MeshError(path + ": the solids enclose no positive volume (turned inside out?)");
  return model;  // checkClosedMesh by readStep: the module calls nothing of libyardsim_forces
}

}  // namespace

}  // namespace yardsim::forces

// (path, tolerance, model) => the model read; MeshError on failure. The module's one entry,
// looked up by this unmangled name.
extern "C" void yardsim_step_read(const std::string& path,
                                  const yardsim::forces::StepTolerance& tolerance,
                                  yardsim::forces::StepModel& model) {
  model = yardsim::forces::readStepOcct(path, tolerance);
}
