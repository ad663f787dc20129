#include "reconfig/sweep/screw_envelope.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace reconfig::sweep {
namespace {

using Eigen::Vector3d;

/// A half-edge's key: its vertices, smaller first, and the face it bounds.
struct HalfEdge {
  std::uint64_t key = 0;
  int face = 0;
  int corner = 0;  ///< the face's corner opposite the edge
};

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

Vector3d vertex(const geometry::Mesh& mesh, int i) { return mesh.V.row(i).transpose(); }

/// −1, 0 or +1: the sign of x, zero within tolerance.
int sign_class(double x, double tolerance) { return x > tolerance ? 1 : (x < -tolerance ? -1 : 0); }

/// The parameter u ∈ (0, 1) where the affine function from fa (u = 0) to fb (u = 1) vanishes,
/// appended when it changes strict sign there.
void push_root(double fa, double fb, double tolerance, std::vector<double>& roots) {
  if (sign_class(fa, tolerance) * sign_class(fb, tolerance) < 0) roots.push_back(fa / (fa - fb));
}

}  // namespace

EnvelopePart::EnvelopePart(const geometry::Mesh& mesh) : mesh_(mesh), normals_(mesh.face_count(), 3) {
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * static_cast<std::size_t>(mesh.face_count()));
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Vector3d a = vertex(mesh, mesh.F(f, 0)), b = vertex(mesh, mesh.F(f, 1)), c = vertex(mesh, mesh.F(f, 2));
    normals_.row(f) = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k)
      half_edges.push_back({edge_key(mesh.F(f, (k + 1) % 3), mesh.F(f, (k + 2) % 3)), f, k});
  }
  std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& x, const HalfEdge& y) { return x.key < y.key; });
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t j = i;
    while (j < half_edges.size() && half_edges[j].key == half_edges[i].key) ++j;
    if (j - i == 2) {
      const HalfEdge& h0 = half_edges[i];
      const HalfEdge& h1 = half_edges[i + 1];
      Edge edge{static_cast<int>(h0.key >> 32), static_cast<int>(h0.key & 0xffffffffu), h0.face, h1.face, false};
      // Convex when the far corner of face 1 lies below face 0's plane.
      const Vector3d n0 = normals_.row(h0.face).transpose();
      const Vector3d across = vertex(mesh, mesh.F(h1.face, h1.corner)) - vertex(mesh, edge.v0);
      edge.convex = n0.dot(across) < -1e-12 * n0.norm() * across.norm();
      edges_.push_back(edge);
    }
    i = j;
  }
}

void screw_velocity(const motion::ScrewMotion& screw, Vector3d& c, Vector3d& omega) {
  const Eigen::Matrix3d back = screw.start().linear().transpose();
  const Vector3d s = back * screw.axis();
  const Vector3d p = screw.start().inverse() * screw.point();
  omega = screw.angle() * s;
  c = screw.distance() * s - omega.cross(p);
}

std::vector<SilhouetteSegment> screw_silhouette(const EnvelopePart& part, const Vector3d& c, const Vector3d& omega) {
  const geometry::Mesh& mesh = part.mesh();
  const Eigen::MatrixX3d& normals = part.normals();
  std::vector<SilhouetteSegment> segments;
  if (mesh.vertex_count() == 0) return segments;
  const double radius = mesh.V.rowwise().norm().maxCoeff();
  const double speed = c.norm() + omega.norm() * radius;
  if (speed == 0.0) return segments;
  Eigen::MatrixX3d velocity(mesh.vertex_count(), 3);
  for (int i = 0; i < mesh.vertex_count(); ++i) velocity.row(i) = (c + omega.cross(vertex(mesh, i))).transpose();
  // f of face `face` at vertex i, and the tolerance under which it counts as zero.
  auto f = [&](int face, int i) { return normals.row(face).dot(velocity.row(i)); };
  auto tolerance = [&](int face) { return 1e-12 * normals.row(face).norm() * speed; };

  for (int face = 0; face < mesh.face_count(); ++face) {
    const double tol = tolerance(face);
    std::array<double, 3> value{};
    std::array<int, 3> sign{};
    for (int k = 0; k < 3; ++k) sign[k] = sign_class(value[k] = f(face, mesh.F(face, k)), tol);
    std::vector<Vector3d> points;
    bool crosses = false;
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.F(face, k), j = mesh.F(face, (k + 1) % 3);
      if (sign[k] == 0) points.push_back(vertex(mesh, i));
      if (sign[k] * sign[(k + 1) % 3] < 0) {
        const double u = value[k] / (value[k] - value[(k + 1) % 3]);
        points.push_back((1 - u) * vertex(mesh, i) + u * vertex(mesh, j));
        crosses = true;
      }
    }
    if (crosses && points.size() == 2) segments.push_back({points[0], points[1], -1});
  }

  std::vector<double> cuts;
  for (int e = 0; e < static_cast<int>(part.edges().size()); ++e) {
    const EnvelopePart::Edge& edge = part.edges()[e];
    if (!edge.convex) continue;
    const double tol0 = tolerance(edge.f0), tol1 = tolerance(edge.f1);
    const double a0 = f(edge.f0, edge.v0), b0 = f(edge.f0, edge.v1);
    const double a1 = f(edge.f1, edge.v0), b1 = f(edge.f1, edge.v1);
    cuts.assign({0.0, 1.0});
    push_root(a0, b0, tol0, cuts);
    push_root(a1, b1, tol1, cuts);
    std::sort(cuts.begin(), cuts.end());
    const Vector3d p0 = vertex(mesh, edge.v0), p1 = vertex(mesh, edge.v1);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double u = 0.5 * (cuts[k] + cuts[k + 1]);
      if (cuts[k + 1] - cuts[k] <= 0.0) continue;
      const int s0 = sign_class((1 - u) * a0 + u * b0, tol0), s1 = sign_class((1 - u) * a1 + u * b1, tol1);
      if (s0 != s1) segments.push_back({(1 - cuts[k]) * p0 + cuts[k] * p1, (1 - cuts[k + 1]) * p0 + cuts[k + 1] * p1, e});
    }
  }
  return segments;
}

namespace {

/// Appends `part` placed by `pose` to `out` (vertices and faces as rows of lists).
void append_pose(const geometry::Mesh& part, const Eigen::Isometry3d& pose, std::vector<Vector3d>& vertices,
                 std::vector<Eigen::Vector3i>& faces) {
  const int base = static_cast<int>(vertices.size());
  for (int i = 0; i < part.vertex_count(); ++i) vertices.push_back(pose * vertex(part, i));
  for (int f = 0; f < part.face_count(); ++f) faces.push_back(part.F.row(f).transpose().array() + base);
}

/// Appends the quads one screw sweeps its silhouette into; returns its step count.
int append_screw(const EnvelopePart& part, const motion::ScrewMotion& screw, const ScrewEnvelopeRequest& request,
                 std::vector<Vector3d>& vertices, std::vector<Eigen::Vector3i>& faces, int& segment_count) {
  Vector3d c, omega;
  screw_velocity(screw, c, omega);
  const std::vector<SilhouetteSegment> segments = screw_silhouette(part, c, omega);
  segment_count += static_cast<int>(segments.size());
  const int steps = std::max(1, static_cast<int>(std::ceil(screw.angle() / request.max_angle_step - 1e-9)));
  std::vector<Eigen::Isometry3d> poses(steps + 1);
  for (int k = 0; k <= steps; ++k) poses[k] = screw.at(static_cast<double>(k) / steps);
  for (const SilhouetteSegment& segment : segments) {
    const int base = static_cast<int>(vertices.size());
    for (int k = 0; k <= steps; ++k) {
      vertices.push_back(poses[k] * segment.a);
      vertices.push_back(poses[k] * segment.b);
    }
    for (int k = 0; k < steps; ++k) {
      const int a = base + 2 * k, b = a + 1, a2 = a + 2, b2 = a + 3;
      faces.emplace_back(a, b, b2);
      faces.emplace_back(a, b2, a2);
    }
  }
  return steps;
}

}  // namespace

ScrewEnvelope screw_envelope(const EnvelopePart& part, std::span<const motion::ScrewMotion> screws,
                             const ScrewEnvelopeRequest& request) {
  ScrewEnvelope envelope;
  std::vector<Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  for (std::size_t j = 0; j < screws.size(); ++j) {
    envelope.steps += append_screw(part, screws[j], request, vertices, faces, envelope.silhouette_segments);
    const bool first = j == 0;
    if (request.poses == EnvelopePoses::every_key || (request.poses == EnvelopePoses::ends && first))
      append_pose(part.mesh(), screws[j].start(), vertices, faces);
  }
  if (!screws.empty() && request.poses != EnvelopePoses::none) append_pose(part.mesh(), screws.back().end(), vertices, faces);
  envelope.mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i) envelope.mesh.V.row(static_cast<Eigen::Index>(i)) = vertices[i].transpose();
  envelope.mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) envelope.mesh.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  return envelope;
}

ScrewEnvelope screw_envelope(const EnvelopePart& part, const motion::ScrewTrack& track,
                             const ScrewEnvelopeRequest& request) {
  std::vector<motion::ScrewMotion> screws;
  for (std::size_t j = 0; j < track.segment_count(); ++j) screws.push_back(track.segment(j));
  return screw_envelope(part, screws, request);
}

}  // namespace reconfig::sweep
