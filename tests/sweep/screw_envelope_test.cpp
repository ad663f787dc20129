#include "reconfig/sweep/screw_envelope.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>

#include "reconfig/geometry/primitives.h"

namespace reconfig::sweep {
namespace {

using Eigen::Vector3d;

Vector3d vertex(const geometry::Mesh& mesh, int i) { return mesh.V.row(i).transpose(); }

/// The mesh vertex at p (within 1e-9), or −1.
int vertex_at(const geometry::Mesh& mesh, const Vector3d& p) {
  for (int i = 0; i < mesh.vertex_count(); ++i)
    if ((vertex(mesh, i) - p).norm() < 1e-9) return i;
  return -1;
}

/// The silhouette for a translation as sorted vertex pairs; fails if a segment is not a whole edge.
std::set<std::pair<int, int>> translation_silhouette(const geometry::Mesh& mesh, const Vector3d& direction) {
  const EnvelopePart part(mesh);
  std::set<std::pair<int, int>> edges;
  for (const SilhouetteSegment& segment : screw_silhouette(part, direction, Vector3d::Zero())) {
    const int a = vertex_at(mesh, segment.a), b = vertex_at(mesh, segment.b);
    EXPECT_GE(a, 0);
    EXPECT_GE(b, 0);
    EXPECT_GE(segment.edge, 0) << "a translation has no silhouette lines across faces";
    edges.insert({std::min(a, b), std::max(a, b)});
  }
  return edges;
}

TEST(ScrewEnvelope, TranslatedBoxSilhouetteIsTheLoopsOfTheFrontAndBackFaces) {
  const geometry::Mesh box = geometry::make_box(Vector3d(2, 1, 3));
  // Analytic: the faces x = ±1 face along/against +x; their 4 + 4 boundary edges (not the diagonals).
  std::set<std::pair<int, int>> expected;
  for (int i = 0; i < box.vertex_count(); ++i)
    for (int j = i + 1; j < box.vertex_count(); ++j) {
      const Vector3d d = vertex(box, j) - vertex(box, i);
      const bool same_side = std::abs(d.x()) < 1e-12;
      const bool axis_edge = (std::abs(d.y()) < 1e-12) != (std::abs(d.z()) < 1e-12);
      if (same_side && axis_edge) expected.insert({i, j});
    }
  ASSERT_EQ(expected.size(), 8u);
  EXPECT_EQ(translation_silhouette(box, Vector3d(0.7, 0, 0)), expected);
}

TEST(ScrewEnvelope, TranslatedSphereSilhouetteIsTheEdgesBetweenFrontAndBackFaces) {
  const geometry::Mesh sphere = geometry::make_sphere(1.0, 3);
  const EnvelopePart part(sphere);
  const Vector3d direction = Vector3d(0.31, -0.47, 0.83);  // generic: no face is tangent to it
  for (int f = 0; f < sphere.face_count(); ++f) ASSERT_GT(std::abs(part.normals().row(f).dot(direction)), 1e-9);
  std::set<std::pair<int, int>> expected;
  for (const EnvelopePart::Edge& edge : part.edges()) {
    const double f0 = part.normals().row(edge.f0).dot(direction), f1 = part.normals().row(edge.f1).dot(direction);
    if (f0 * f1 < 0) expected.insert({std::min(edge.v0, edge.v1), std::max(edge.v0, edge.v1)});
  }
  ASSERT_GT(expected.size(), 20u);
  EXPECT_EQ(translation_silhouette(sphere, direction), expected);
}

TEST(ScrewEnvelope, VelocityFieldMatchesTheScrewsFiniteDifference) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Isometry3d A = Eigen::Isometry3d::Identity(), B = Eigen::Isometry3d::Identity();
    A.translate(Vector3d(normal(rng), normal(rng), normal(rng))).rotate(Eigen::Quaterniond::UnitRandom());
    B.translate(Vector3d(normal(rng), normal(rng), normal(rng))).rotate(Eigen::Quaterniond::UnitRandom());
    const motion::ScrewMotion screw(A, B);
    Vector3d c, omega;
    screw_velocity(screw, c, omega);
    const Vector3d q(normal(rng), normal(rng), normal(rng));
    const double t = 0.3, h = 1e-6;
    // In the rest frame: the world velocity taken back by the pose's rotation at t.
    const Vector3d world = (screw.at(t + h) * q - screw.at(t - h) * q) / (2 * h);
    const Vector3d body = screw.at(t).linear().transpose() * world;
    EXPECT_LT((body - (c + omega.cross(q))).norm(), 1e-6) << "trial " << trial;
  }
}

/// True when the ray from `origin` along `direction` hits triangle (a, b, c) (Möller–Trumbore, t > 0).
bool ray_hits(const Vector3d& origin, const Vector3d& direction, const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const Vector3d e1 = b - a, e2 = c - a, p = direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return false;
  const Vector3d s = origin - a;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return false;
  const Vector3d q = s.cross(e1);
  const double v = direction.dot(q) / det;
  if (v < 0 || u + v > 1) return false;
  return e2.dot(q) / det > 0;
}

bool ray_hits_mesh(const Vector3d& origin, const Vector3d& direction, const geometry::Mesh& mesh) {
  for (int f = 0; f < mesh.face_count(); ++f)
    if (ray_hits(origin, direction, vertex(mesh, mesh.F(f, 0)), vertex(mesh, mesh.F(f, 1)), vertex(mesh, mesh.F(f, 2))))
      return true;
  return false;
}

/// A star-shaped prism: a cylinder whose ring is pushed in and out (concave edges).
geometry::Mesh star_prism() {
  geometry::Mesh mesh = geometry::make_cylinder(1.0, 0.8, 24);
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const double angle = std::atan2(mesh.V(i, 1), mesh.V(i, 0));
    const double scale = 0.7 + 0.3 * std::cos(6 * angle);
    mesh.V(i, 0) *= scale;
    mesh.V(i, 1) *= scale;
  }
  return mesh;
}

/// Rays from points of the moving part that escape `bound` (hit none of its triangles).
///
/// The oracle: the boundary of the swept region lies in the envelope ∪ the end poses, so a ray
/// from any point of the region to infinity must cross one of their triangles. (Parity cannot
/// be used: the envelope is a superset with sheets inside the region.) Points are taken on the
/// part's surface at random times, pushed inward by `inset` to stay clear of the chordal
/// approximation of the helical quads (its deviation here is below 1e-4). A missing strip of
/// quads lets rays through: the negative control below sees it.
int escaping_rays(const geometry::Mesh& part, const std::vector<motion::ScrewMotion>& screws,
                  const geometry::Mesh& bound, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(0, 1);
  std::normal_distribution<double> normal;
  const double inset = 1e-3;
  int escaped = 0;
  for (int sample = 0; sample < 150; ++sample) {
    const motion::ScrewMotion& screw = screws[rng() % screws.size()];
    const int face = static_cast<int>(rng() % part.face_count());
    double u = uniform(rng), v = uniform(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vector3d a = vertex(part, part.F(face, 0)), b = vertex(part, part.F(face, 1)), c = vertex(part, part.F(face, 2));
    const Vector3d n = (b - a).cross(c - a).normalized();
    const Vector3d q = a + u * (b - a) + v * (c - a) - inset * n;
    const Vector3d x = screw.at(uniform(rng)) * q;
    for (int ray = 0; ray < 6; ++ray) {
      const Vector3d direction(normal(rng), normal(rng), normal(rng));
      if (!ray_hits_mesh(x, direction, bound)) ++escaped;
    }
  }
  return escaped;
}

std::vector<motion::ScrewMotion> random_track(std::mt19937& rng, int pieces) {
  std::normal_distribution<double> normal;
  std::vector<Eigen::Isometry3d> keys(pieces + 1, Eigen::Isometry3d::Identity());
  for (Eigen::Isometry3d& key : keys)
    key.translate(1.5 * Vector3d(normal(rng), normal(rng), normal(rng))).rotate(Eigen::Quaterniond::UnitRandom());
  std::vector<motion::ScrewMotion> screws;
  for (int j = 0; j < pieces; ++j) screws.emplace_back(keys[j], keys[j + 1]);
  return screws;
}

TEST(ScrewEnvelope, EveryPointOfTheMovingPartIsEnclosedByTheEnvelopeAndEndPoses) {
  std::mt19937 rng(21);
  const std::vector<geometry::Mesh> parts = {geometry::make_box(Vector3d(1, 0.6, 1.4)), geometry::make_sphere(0.8, 2),
                                             star_prism()};
  ScrewEnvelopeRequest request;
  request.max_angle_step = 0.02;  // chords within r·(1 − cos 0.01) < 1e-4 of the helices
  request.poses = EnvelopePoses::every_key;
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (int pieces : {1, 3}) {
      const std::vector<motion::ScrewMotion> screws = random_track(rng, pieces);
      const EnvelopePart part(parts[p]);
      const ScrewEnvelope envelope = screw_envelope(part, screws, request);
      ASSERT_GT(envelope.silhouette_segments, 0);
      EXPECT_EQ(escaping_rays(parts[p], screws, envelope.mesh, rng), 0) << "part " << p << ", " << pieces << " screws";
    }
}

TEST(ScrewEnvelope, TheOracleSeesAMissingEnvelope) {
  std::mt19937 rng(3);
  const geometry::Mesh box = geometry::make_box(Vector3d(1, 0.6, 1.4));
  const std::vector<motion::ScrewMotion> screws = random_track(rng, 1);
  ScrewEnvelopeRequest request;
  request.max_angle_step = 0.02;
  const EnvelopePart part(box);
  const ScrewEnvelope full = screw_envelope(part, screws, request);
  ASSERT_EQ(escaping_rays(box, screws, full.mesh, rng), 0);
  // Only the end poses (the envelope without its quads) must let rays out.
  request.poses = EnvelopePoses::ends;
  geometry::Mesh ends = screw_envelope(part, screws, request).mesh;
  const int quad_triangles = full.mesh.face_count() - 2 * box.face_count();
  ends.F = ends.F.bottomRows(2 * box.face_count()).eval();
  ASSERT_GT(quad_triangles, 0);
  EXPECT_GT(escaping_rays(box, screws, ends, rng), 0);
}

double distance_to_segment(const Vector3d& x, const Vector3d& a, const Vector3d& b) {
  const double u = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (x - (a + u * (b - a))).norm();
}

/// Against dense sampling of n·v on every face and convex edge, for random screws: every sampled
/// point of a convex edge whose two faces move strictly in opposite directions lies on an edge
/// segment of that edge, every edge segment's midpoint has faces of different signs, every face
/// segment lies on its zero line, and the faces the sampling sees both signs on are as many as
/// the face segments.
TEST(ScrewEnvelope, SilhouetteMatchesDenseSampling) {
  std::mt19937 rng(8);
  const std::vector<geometry::Mesh> meshes = {star_prism(), geometry::make_sphere(1.0, 1)};
  for (const geometry::Mesh& mesh : meshes)
    for (int trial = 0; trial < 5; ++trial) {
      const motion::ScrewMotion screw = random_track(rng, 1)[0];
      Vector3d c, omega;
      screw_velocity(screw, c, omega);
      const EnvelopePart part(mesh);
      const std::vector<SilhouetteSegment> segments = screw_silhouette(part, c, omega);
      auto f = [&](int face, const Vector3d& q) { return part.normals().row(face).dot(c + omega.cross(q)); };
      const double tiny = 1e-9 * (c.norm() + 2 * omega.norm()) * part.normals().rowwise().norm().maxCoeff();
      for (int e = 0; e < static_cast<int>(part.edges().size()); ++e) {
        const EnvelopePart::Edge& edge = part.edges()[e];
        if (!edge.convex) continue;
        for (int k = 0; k <= 100; ++k) {
          const Vector3d x = vertex(mesh, edge.v0) + (k / 100.0) * (vertex(mesh, edge.v1) - vertex(mesh, edge.v0));
          const double f0 = f(edge.f0, x), f1 = f(edge.f1, x);
          if (!((f0 > tiny && f1 < -tiny) || (f0 < -tiny && f1 > tiny))) continue;
          const bool covered = std::any_of(segments.begin(), segments.end(), [&](const SilhouetteSegment& s) {
            return s.edge == e && distance_to_segment(x, s.a, s.b) < 1e-9;
          });
          EXPECT_TRUE(covered) << "edge " << e << " at " << k / 100.0;
        }
      }
      int face_segments = 0;
      for (const SilhouetteSegment& segment : segments) {
        const Vector3d mid = (segment.a + segment.b) / 2;
        if (segment.edge >= 0) {
          const EnvelopePart::Edge& edge = part.edges()[segment.edge];
          EXPECT_TRUE(edge.convex);
          EXPECT_LE(f(edge.f0, mid) * f(edge.f1, mid), tiny * tiny);
          continue;
        }
        ++face_segments;
        bool on_some_zero_line = false;  // the face is not stored: some face's plane and zero line hold it
        for (int face = 0; face < mesh.face_count() && !on_some_zero_line; ++face) {
          const Vector3d n = part.normals().row(face).normalized().transpose();
          const Vector3d a = vertex(mesh, mesh.F(face, 0));
          on_some_zero_line = std::abs(n.dot(segment.a - a)) < 1e-9 && std::abs(n.dot(segment.b - a)) < 1e-9 &&
                              std::abs(f(face, segment.a)) < tiny && std::abs(f(face, segment.b)) < tiny;
        }
        EXPECT_TRUE(on_some_zero_line);
      }
      int mixed_faces = 0;
      for (int face = 0; face < mesh.face_count(); ++face) {
        bool positive = false, negative = false;
        const Vector3d a = vertex(mesh, mesh.F(face, 0)), b = vertex(mesh, mesh.F(face, 1)), cc = vertex(mesh, mesh.F(face, 2));
        for (int i = 0; i <= 40; ++i)
          for (int j = 0; i + j <= 40; ++j) {
            const double value = f(face, a + (i / 40.0) * (b - a) + (j / 40.0) * (cc - a));
            positive |= value > tiny;
            negative |= value < -tiny;
          }
        mixed_faces += positive && negative;
      }
      EXPECT_EQ(face_segments, mixed_faces);
    }
}

TEST(ScrewEnvelope, ConcaveEdgesGiveNoSilhouetteAndConvexOnesAreFound) {
  const EnvelopePart part(star_prism());
  int convex = 0, concave = 0;
  for (const EnvelopePart::Edge& edge : part.edges()) (edge.convex ? convex : concave)++;
  EXPECT_GT(convex, 0);
  EXPECT_GT(concave, 0);
  const Vector3d direction(1, 0.2, 0);
  for (const SilhouetteSegment& segment : screw_silhouette(part, direction, Vector3d::Zero()))
    if (segment.edge >= 0) {
      EXPECT_TRUE(part.edges()[segment.edge].convex);
    }
}

TEST(ScrewEnvelope, AnEmptyPartHasAnEmptyEnvelope) {
  const EnvelopePart part{geometry::Mesh{}};
  const motion::ScrewMotion screw(Eigen::Isometry3d::Identity(), Eigen::Isometry3d(Eigen::Translation3d(1, 0, 0)));
  const ScrewEnvelope envelope = screw_envelope(part, std::span(&screw, 1));
  EXPECT_EQ(envelope.silhouette_segments, 0);
  EXPECT_TRUE(envelope.mesh.empty());
}

TEST(ScrewEnvelope, TrackEnvelopeCoversEverySegment) {
  const geometry::Mesh box = geometry::make_box(Vector3d(1, 1, 1));
  std::vector<motion::ScrewKey> keys(3);
  keys[1].time = 0.5;
  keys[1].pose.translation = Vector3d(2, 0, 0);
  keys[2].time = 1.0;
  keys[2].pose.translation = Vector3d(2, 2, 0);
  const motion::ScrewTrack track(keys, Vector3d::Zero());
  const EnvelopePart part(box);
  const ScrewEnvelope envelope = screw_envelope(part, track);
  EXPECT_EQ(envelope.steps, 2);                // two translations, one step each
  EXPECT_EQ(envelope.silhouette_segments, 16);  // the two loops of 4 edges, per translation
  EXPECT_EQ(envelope.mesh.face_count(), 16 * 2 + 2 * 12);
}

}  // namespace
}  // namespace reconfig::sweep
