#include "reconfig/sweep/carve_part.h"

#include <cassert>

#include "reconfig/geometry/mass_properties.h"
#include "reconfig/sweep/subtract_meshes.h"

namespace reconfig::sweep {

std::vector<SweptVolumeResult> carver_sweeps(const scene::Reconfigurable& scene, const CarveRequest& request) {
  const geometry::Mesh& solid = scene.parts[request.part].mesh;
  const double count = static_cast<double>(request.carvers.size());
  std::vector<SweptVolumeResult> sweeps;
  for (std::size_t i = 0; i < request.carvers.size(); ++i) {
    assert(request.carvers[i] != request.part);
    SweptVolumeRequest sweep = request.sweep;
    sweep.clip = Eigen::AlignedBox3d(solid.V.colwise().minCoeff().transpose(), solid.V.colwise().maxCoeff().transpose());
    sweep.progress = [&, i](double fraction) { return report_progress(request.progress, (double(i) + fraction) / count); };
    const RelativeMotion motion =
        relative_motion(scene, request.transition, request.carvers[i], request.part, request.t0, request.t1);
    sweeps.push_back(swept_volume(scene.parts[request.carvers[i]].mesh, motion, sweep));
    if (sweeps.back().cancelled) break;
  }
  return sweeps;
}

CarveResult carve_part(const scene::Reconfigurable& scene, const CarveRequest& request) {
  CarveResult result;
  const geometry::Mesh& solid = scene.parts[request.part].mesh;
  result.mesh = solid;
  result.volume_before = result.volume_after = geometry::mass_properties(solid).volume;
  // Progress: the sweeps take 80 %, the subtraction 20 %.
  CarveRequest sweeping = request;
  sweeping.progress = [&](double fraction) { return report_progress(request.progress, 0.8 * fraction); };
  result.sweeps = carver_sweeps(scene, sweeping);
  if (!result.sweeps.empty() && result.sweeps.back().cancelled) return result.cancelled = true, result;
  std::vector<geometry::Mesh> cutters;
  std::vector<int> cutter_carver;  // the carver of each cutter
  for (std::size_t i = 0; i < result.sweeps.size(); ++i) {
    if (result.sweeps[i].mesh.empty()) continue;  // the sweep misses A
    cutters.push_back(result.sweeps[i].mesh);
    cutter_carver.push_back(request.carvers[i]);
  }
  const SubtractionResult difference = subtract_meshes(solid, cutters, [&](double fraction) {
    return report_progress(request.progress, 0.8 + 0.2 * fraction);
  });
  if (difference.cancelled) return result.cancelled = true, result;
  if (!difference.ok()) {
    result.problem = difference.problem;
    for (std::size_t i = 0; i < cutters.size(); ++i) {  // name the carvers, not their cutter's index
      const std::string label = "cutter " + std::to_string(i + 1) + ":";
      if (result.problem.rfind(label, 0) == 0)
        result.problem = "the swept volume of " + scene.parts[cutter_carver[i]].name + ":" + result.problem.substr(label.size());
    }
    return result;
  }
  result.mesh = difference.mesh;
  result.volume_after = geometry::mass_properties(result.mesh).volume;
  return result;
}

}  // namespace reconfig::sweep
