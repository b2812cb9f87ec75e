#pragma once
// Nonlinear hydrostatics (and the simplest nonlinear Froude-Krylov force in waves) on one body:
// at every stage the hull mesh is clipped at the instantaneous water surface (calm plane or the
// incident wave elevation) and the incident pressure is integrated over the wetted surface
// (forces/geometry/submerged_mesh.hpp). Large heel, trim, capsize, a fully submerged or a dry
// hull all work. Calm water: the force is rho g V up through the centre of buoyancy and is
// conservative with potential energy rho g V (level - z_B). In waves the potential reported is
// the same calm-water one, and power() is the power of the difference between the wave and the
// calm-water forces, so the energy balance closes in waves too. Allocation-free given its
// scratch (the clipping workspace, makeScratch()).
// Linear form (incidentPressure false): the hull is clipped at the still-water level at every
// stage whatever the sea, and no incident pressure is integrated: the restoring force alone
// (conservative, power 0). The waves' force (Froude-Krylov + diffraction) must then come from the
// body's hydrodynamics (the impulse-response excitation with Froude-Krylov): the form
// impulse-response codes use, and about a hundred times cheaper in a 200-component sea.
#include <memory>
#include <string>

#include "forces/airy_waves.hpp"
#include "forces/force_provider.hpp"
#include "forces/geometry/submerged_mesh.hpp"
#include "forces/geometry/triangle_mesh.hpp"

namespace yardsim::forces {

// What a naval architect reads off a floating body at one instant.
struct HydrostaticReport {
  SubmergedProperties submerged;  // volume, centre of buoyancy, waterplane, force, moment (world)
  double displacement = 0.0;      // kg: rho V
  double draft = 0.0;  // m: still-water level minus z of the keel point (docs/hydrostatics.md)
  double heel = 0.0;   // rad: roll of the body about its x axis
  double trim = 0.0;   // rad: pitch of the body about its y axis (bow down > 0)
  double gmTransverse = 0.0;    // m: z_B - z_G + I_T / V (0 when dry)
  double gmLongitudinal = 0.0;  // m: z_B - z_G + I_L / V
};

class Hydrostatics final : public ForceProvider {
 public:
  // (name, model, body >= 1, hull in the body frame, the sea, clip at the incident surface and
  // integrate its pressure (true) or clip at the still-water level (false)) => the provider. The
  // hull is checked (checkClosedMesh); throws std::invalid_argument naming the provider and the
  // mesh's own complaint, or a body outside the model.
  Hydrostatics(std::string name, const dynamics::Model& model, int body, TriangleMesh hull,
               std::shared_ptr<const AiryWaves> sea, bool incidentPressure = true);
  bool incidentPressure() const { return incident_; }

  int body() const { return body_; }
  const TriangleMesh& hull() const { return hull_; }
  const AiryWaves& sea() const { return *sea_; }
  // (hull) => its solid's volume, centroid, inertia (body frame; computed once)
  const SolidProperties& solid() const { return solid_; }
  // (stage) => the report there
  HydrostaticReport report(const Stage& s) const;

  // the scratch: the workspace the hull is clipped in, and the last two clippings at each surface
  // (the sea, calm water) with the time and pose they were for, given again when asked for the
  // same ones (the power at a step's end is asked again at the next step's start and first stage;
  // the energy of a step's end is read by the samples after the next step was computed)
  struct Scratch final : ProviderScratch {
    Scratch(const TriangleMesh& hull, std::size_t components) : ws(hull, components) {}
    SubmergedWorkspace ws;
    struct Last {
      const AiryWaves* sea = nullptr;  // nullptr: nothing yet
      double t = 0.0;
      dynamics::Transform X_WB;
      SubmergedProperties p;
      bool all = false;        // p holds every integral, not the force and moment alone
      unsigned long when = 0;  // the number of the clipping: the larger, the newer
    };
    Last last[2][2];              // [0] the sea, [1] calm water (and the sea while it is calm)
    unsigned long clippings = 0;  // clippings done in this scratch
  };
  std::unique_ptr<ProviderScratch> makeScratch() const override;

 protected:
  void doEvaluate(const Stage& s, dynamics::ExternalForces& f, Eigen::VectorXd& tau) const override;
  // rho g V_calm (level - z_B,calm): the calm-water restoring potential
  double doPotentialEnergy(const Stage& s) const override;
  // waves: (F, M)_waves - (F, M)_calm against the body's velocity; calm water: 0
  double doPower(const Stage& s) const override;

 private:
  int body_;
  TriangleMesh hull_;
  SolidProperties solid_;
  dynamics::Vector3 keel_B_;  // the keel point: solid centroid x, y at the lowest z of the hull
  std::shared_ptr<const AiryWaves> sea_;
  AiryWaves calm_;            // the same water without waves
  std::vector<int> subtree_;  // body and its descendants: G for GM
  bool incident_ = true;      // clipped at the incident surface with its pressure
  // (the surface the hull is clipped at) => the sea, or the calm water in the linear form
  const AiryWaves& surface() const { return incident_ ? *sea_ : calm_; }
  // (stage, surface: *sea_ or calm_, the integrals needed) => integrateSubmerged at the stage's
  // pose and time, or the scratch's copy when it was for the same time and pose (bit for bit) and
  // holds those integrals. The forces (evaluate, power in waves) need the force and moment alone;
  // the potential energy and the report every integral. Before its waves start (ramp 0) and
  // without waves the sea is calm water, whose clipping gives the same doubles: one cache for both.
  SubmergedProperties submerged(const Stage& s, const AiryWaves& surface,
                                SubmergedIntegrals which = SubmergedIntegrals::All) const;
};

}  // namespace yardsim::forces
