#pragma once
/// @file
/// The envelope a part sweeps along screw motions: its silhouette edges swept into quads
/// (Rossignac & Kim, "Animating and sweeping polyhedra along interpolating screw motions").

#include <Eigen/Core>

#include <span>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/motion/screw_motion.h"
#include "reconfig/motion/screw_track.h"

namespace reconfig::sweep {

/// A closed triangle mesh with what the silhouettes need, computed once per mesh (the studio
/// keeps it while keys are dragged): outward face normals (not normalized, |n| = 2·area) and
/// every edge with its two faces and whether it is convex.
class EnvelopePart {
 public:
  /// @param mesh  a closed, outward triangle mesh (#V×3, #F×3); an edge with other than two
  ///              faces is skipped (only face silhouettes are found on it)
  explicit EnvelopePart(const geometry::Mesh& mesh);

  struct Edge {
    int v0 = 0, v1 = 0;      ///< vertex indices
    int f0 = 0, f1 = 0;      ///< the two faces
    bool convex = false;     ///< the solid's dihedral angle at the edge is below 180°
  };

  const geometry::Mesh& mesh() const { return mesh_; }
  const Eigen::MatrixX3d& normals() const { return normals_; }  ///< #F×3
  const std::vector<Edge>& edges() const { return edges_; }

 private:
  geometry::Mesh mesh_;
  Eigen::MatrixX3d normals_;
  std::vector<Edge> edges_;
};

/// A piece of the silhouette, in the part's rest frame.
struct SilhouetteSegment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  /// The mesh edge it lies on (index into `EnvelopePart::edges()`), or −1 for a silhouette
  /// line across a face.
  int edge = -1;
};

/// The silhouette of the part for the screw velocity field v(q) = c + ω × q (rest frame): the
/// points whose velocity is tangent to the surface.
/// - On each face with normal n, f(q) = n·v(q) is affine: the segment where f = 0 crosses
///   the face (the silhouette line trimmed to the face). A face with f ≡ 0 (to 1e-12
///   relative) is tangent to the motion and gives none: its boundary edges do.
/// - On each convex edge, the sub-segments (split at the characteristic points, the roots of
///   f for either face) where the two faces' f have different signs (−, 0, +): one face moves
///   forward and the other backward or along itself. Concave edges give no silhouette.
/// @param part   the mesh with its normals and edges
/// @param c, omega  the velocity field: v(q) = c + omega × q
std::vector<SilhouetteSegment> screw_silhouette(const EnvelopePart& part, const Eigen::Vector3d& c,
                                                const Eigen::Vector3d& omega);

/// The velocity field of `screw` in the rest frame of the part it moves (rest point q is at
/// screw.at(t)·q): constant in that frame. Written as v(q) = c + ω × q: ω = b·s', c = d·s' −
/// b·s' × p', with s', p' the axis direction and point taken back by screw.start()⁻¹.
void screw_velocity(const motion::ScrewMotion& screw, Eigen::Vector3d& c, Eigen::Vector3d& omega);

/// Which poses of the part the envelope mesh also holds.
enum class EnvelopePoses {
  none,       ///< only the swept quads
  ends,       ///< the part at the first screw's start and the last screw's end
  every_key,  ///< the part at the start of every screw and at the last end
};

struct ScrewEnvelopeRequest {
  /// Each screw is cut into ceil(angle / max_angle_step) steps (at least one; a translation
  /// takes one, exact); radians, > 0. Every quad's corners lie on the exact envelope; the
  /// chord of an arc of radius r deviates from it by at most r·(1 − cos(step/2)).
  double max_angle_step = 0.0872664626;  // 5°
  EnvelopePoses poses = EnvelopePoses::ends;
};

struct ScrewEnvelope {
  /// Triangulated quads (two triangles per silhouette segment per step), unoriented, in world
  /// space, followed by the requested poses of the part (vertices not shared between quads).
  geometry::Mesh mesh;
  int silhouette_segments = 0;  ///< summed over the screws
  int steps = 0;                ///< summed over the screws
};

/// The envelope of the part moved by the screws in turn, each from its parameter 0 to 1: a
/// superset of the boundary of the region it sweeps, together with the poses at the screws'
/// ends (the boundary of a sweep lies in the sweep of its silhouette and its end poses; with
/// `EnvelopePoses::ends` across several screws the joints, where the velocity jumps, are
/// only covered to within how far one screw differs from the next).
/// @param part     the part in its rest frame
/// @param screws   rest point q is at screws[j].at(t)·q during screw j
/// @param request  steps, poses
ScrewEnvelope screw_envelope(const EnvelopePart& part, std::span<const motion::ScrewMotion> screws,
                             const ScrewEnvelopeRequest& request = {});

/// The envelope along every segment of a piecewise screw track.
ScrewEnvelope screw_envelope(const EnvelopePart& part, const motion::ScrewTrack& track,
                             const ScrewEnvelopeRequest& request = {});

}  // namespace reconfig::sweep
