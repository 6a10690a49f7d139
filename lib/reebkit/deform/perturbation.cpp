#include "reebkit/deform/perturbation.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/mesh/resampling.h"

#include <sstream>

namespace reebkit {

MeshVariant perturb_mesh(const Mesh& mesh, const Perturbation& p, const MeshAnalysis* analysis,
                         std::vector<std::string>* notes) {
  switch (p.kind) {
    case PerturbationKind::Decimate: return decimate_mesh(mesh, DecimationOptions{p.amount, 0.02});
    case PerturbationKind::Remesh: return remesh(mesh, p.remesh);
    case PerturbationKind::Subdivide: return subdivide_mesh(mesh, static_cast<int>(p.amount));
    case PerturbationKind::Noise:
      return same_vertices(add_normal_noise(mesh, NoiseOptions{p.amount, p.seed, NoiseShape::Gaussian}));
    case PerturbationKind::Pose: break;
  }
  if (!analysis) throw InvalidArgument("perturb_mesh: a pose needs the analysis of the mesh");
  PoseOptions options = p.pose;
  options.seed = p.seed;
  const RandomPose pose = random_pose(*analysis, options);
  if (notes) {
    notes->insert(notes->end(), pose.skipped.begin(), pose.skipped.end());
    std::ostringstream turned;
    turned << pose.turns.size() << " leaf component(s) turned by";
    for (const Deformation& turn : pose.turns) turned << " " << turn.angle_degrees;
    notes->push_back(turned.str() + " degrees");
  }
  // Without the vertices the analysis added to fill small holes.
  return same_vertices(original_surface(pose.mesh));
}

}  // namespace reebkit
