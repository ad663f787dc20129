#include "reconfig/motion/motion_bounds.h"

#include "motion/detail/key_times.h"
#include "motion/detail/so3.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace reconfig::motion {

using detail::KeyLocation;

namespace {

/// t0, the key times strictly inside (t0, t1), t1.
std::vector<double> breakpoints(const std::vector<double>& key_times, double t0, double t1) {
  std::vector<double> b{t0};
  for (double s : key_times)
    if (s > t0 && s < t1) b.push_back(s);
  b.push_back(t1);
  return b;
}

/// Segment containing the open piece (a, b) (a < b), or none when the track is constant
/// there (before the first key, after the last, single key).
struct PieceSegment {
  bool moving = false;
  std::size_t j = 0;
  double fa = 0.0, fb = 0.0;  ///< segment parameters at a and b
};

PieceSegment piece_segment(const std::vector<double>& times, double a, double b) {
  PieceSegment p;
  const KeyLocation loc = detail::locate(times, 0.5 * (a + b));
  if (loc.region != KeyLocation::Region::kInside) return p;
  p.moving = true;
  p.j = loc.segment;
  const double s0 = times[p.j], ds = times[p.j + 1] - s0;
  p.fa = std::clamp((a - s0) / ds, 0.0, 1.0);
  p.fb = std::clamp((b - s0) / ds, 0.0, 1.0);
  return p;
}

/// Blossom of the cubic with control points P at (u1, u2, u3).
Eigen::Vector3d blossom(const std::array<Eigen::Vector3d, 4>& P, double u1, double u2,
                        double u3) {
  std::array<Eigen::Vector3d, 3> l1;
  for (int i = 0; i < 3; ++i) l1[i] = (1 - u1) * P[i] + u1 * P[i + 1];
  std::array<Eigen::Vector3d, 2> l2;
  for (int i = 0; i < 2; ++i) l2[i] = (1 - u2) * l1[i] + u2 * l1[i + 1];
  return (1 - u3) * l2[0] + u3 * l2[1];
}

/// max over f ∈ [0,1] of 3f(1−f)((1−f)α + fβ), α, β >= 0.
double cubic_hump_max(double alpha, double beta) {
  auto h = [&](double f) { return 3.0 * f * (1.0 - f) * ((1.0 - f) * alpha + f * beta); };
  double best = 0.0;
  // h'(f)/3 = 3(α − β) f² + (2β − 4α) f + α
  const double A = 3.0 * (alpha - beta), B = 2.0 * beta - 4.0 * alpha, C = alpha;
  std::vector<double> roots;
  if (std::abs(A) < 1e-300) {
    if (B != 0.0) roots.push_back(-C / B);
  } else {
    const double disc = B * B - 4.0 * A * C;
    if (disc >= 0.0) {
      const double sq = std::sqrt(disc);
      const double q = -0.5 * (B + std::copysign(sq, B));
      if (q != 0.0) roots.push_back(C / q);
      roots.push_back(q / A);
    }
  }
  for (double f : roots)
    if (f > 0.0 && f < 1.0) best = std::max(best, h(f));
  // Guard against rounding in the roots: also try a few fixed points.
  for (double f : {1.0 / 3.0, 0.5, 2.0 / 3.0}) best = std::max(best, h(f));
  return best;
}

double operator_norm(const Eigen::Matrix3d& M) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M.transpose() * M,
                                                         Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, es.eigenvalues().maxCoeff()));
}

double lerp_weight(double t, double t0, double t1) { return t1 > t0 ? (t - t0) / (t1 - t0) : 0.0; }

/// Shared bookkeeping: the part's center follows xc(t), its frame turns by R(t), given at the
/// breakpoints `bps` of [t0, t1] (the first is t0, the last t1). Each piece [a, b] reports a
/// bound on its own chord deviation; this adds the (linear) difference between piece chords
/// and the interval chord, measured at the breakpoints: per breakpoint, how far the path is
/// there from the interval's chord (`distance` of the difference: a norm).
template <class Value, class Distance>
std::vector<double> chord_gaps(const std::vector<double>& bps, const std::vector<Value>& path, Distance distance) {
  const double t0 = bps.front(), t1 = bps.back();
  std::vector<double> gaps;
  gaps.reserve(bps.size());
  gaps.push_back(0.0);  // the chord passes through the path's ends
  for (std::size_t k = 1; k + 1 < bps.size(); ++k) {
    const double w = lerp_weight(bps[k], t0, t1);
    gaps.push_back(distance(Value(path[k] - ((1 - w) * path.front() + w * path.back()))));
  }
  if (bps.size() > 1) gaps.push_back(0.0);
  return gaps;
}

double center_distance(const Eigen::Vector3d& v) { return v.norm(); }

}  // namespace

MotionBound keyframed_motion_bound(const BezierTranslationTrack& translation,
                                   const SlerpRotationTrack& rotation, double radius, double t0,
                                   double t1) {
  assert(t0 <= t1 && radius >= 0.0);
  MotionBound out;
  if (!(t1 > t0)) return out;

  // Translation.
  const std::vector<double>& xt = translation.key_times();
  const std::vector<double> xb = breakpoints(xt, t0, t1);
  std::vector<Eigen::Vector3d> x;
  for (double t : xb) x.push_back(translation.evaluate(t));
  const std::vector<double> x_gaps = chord_gaps(xb, x, center_distance);
  const Eigen::Vector3d& x_start = x.front();
  double x_dev = 0.0, x_disp = 0.0;
  for (std::size_t i = 0; i + 1 < xb.size(); ++i) {
    const PieceSegment ps = piece_segment(xt, xb[i], xb[i + 1]);
    double own = 0.0;
    if (ps.moving) {
      const auto P = translation.control_points(ps.j);
      const std::array<Eigen::Vector3d, 4> Q = {
          blossom(P, ps.fa, ps.fa, ps.fa), blossom(P, ps.fa, ps.fa, ps.fb),
          blossom(P, ps.fa, ps.fb, ps.fb), blossom(P, ps.fb, ps.fb, ps.fb)};
      const double a = (Q[1] - (2.0 * Q[0] + Q[3]) / 3.0).norm();
      const double b = (Q[2] - (Q[0] + 2.0 * Q[3]) / 3.0).norm();
      own = cubic_hump_max(a, b);
      for (const Eigen::Vector3d& q : Q) x_disp = std::max(x_disp, (q - x_start).norm());
    } else {
      x_disp = std::max(x_disp, (x[i] - x_start).norm());
    }
    x_dev = std::max(x_dev, own + std::max(x_gaps[i], x_gaps[i + 1]));
  }

  // Rotation.
  double r_dev = 0.0, turned = 0.0;
  if (radius > 0.0) {
    const std::vector<double>& rt = rotation.key_times();
    const std::vector<double> rb = breakpoints(rt, t0, t1);
    std::vector<Eigen::Matrix3d> frames;
    for (double t : rb) frames.push_back(rotation.evaluate(t).toRotationMatrix());
    const std::vector<double> r_gaps = chord_gaps(rb, frames, operator_norm);
    for (std::size_t i = 0; i + 1 < rb.size(); ++i) {
      const PieceSegment ps = piece_segment(rt, rb[i], rb[i + 1]);
      double own = 0.0;
      if (ps.moving) {
        const double psi = rotation.segment_rotation_vector(ps.j).norm() * (ps.fb - ps.fa);
        own = detail::arc_chord_deviation(psi);
        turned += psi;
      }
      r_dev = std::max(r_dev, own + std::max(r_gaps[i], r_gaps[i + 1]));
    }
  }
  out.deviation = x_dev + radius * r_dev;
  out.displacement = x_disp + radius * 2.0 * std::sin(0.5 * std::min(turned, M_PI));
  return out;
}

MotionBound screw_motion_bound(const ScrewTrack& track, double radius, double t0, double t1) {
  assert(t0 <= t1 && radius >= 0.0);
  MotionBound out;
  if (!(t1 > t0)) return out;
  const Eigen::Vector3d& c = track.center();
  const std::vector<double>& st = track.key_times();
  const std::vector<double> sb = breakpoints(st, t0, t1);
  std::vector<Eigen::Vector3d> centers;
  std::vector<Eigen::Matrix3d> frames;
  for (double t : sb) {
    const Eigen::Isometry3d pose = track.at(t);
    centers.push_back(pose * c);
    frames.push_back(pose.linear());
  }
  const std::vector<double> x_gaps = chord_gaps(sb, centers, center_distance);
  const std::vector<double> r_gaps = radius > 0.0 ? chord_gaps(sb, frames, operator_norm) : std::vector<double>();
  const Eigen::Vector3d& x_start = centers.front();

  double x_dev = 0.0, r_dev = 0.0, x_disp = 0.0, turned = 0.0;
  for (std::size_t i = 0; i + 1 < sb.size(); ++i) {
    const PieceSegment ps = piece_segment(st, sb[i], sb[i + 1]);
    double own_x = 0.0, own_r = 0.0, arc = 0.0;
    if (ps.moving) {
      const ScrewMotion& m = track.segment(ps.j);
      const double b = m.angle(), df = ps.fb - ps.fa, psi = b * df;
      const Eigen::Vector3d& s = m.axis();
      Eigen::Vector3d chord = m.end() * c - m.start() * c;
      const double along = chord.dot(s);
      chord -= along * s;
      const double ell = chord.norm();  // = 2 ρ sin(b/2)
      // b / sin(b/2) → 2 as b → 0.
      const double b_over_sin = b == 0.0 ? 2.0 : b / std::sin(0.5 * b);
      const double rho_b = 0.5 * ell * b_over_sin;  // ρ b, the angular part of the speed
      if (psi * psi / 8.0 < 2.0) {
        own_x = rho_b * b * df * df / 8.0;  // ρ ψ² / 8
      } else {
        own_x = ell / std::sin(0.5 * b);  // 2ρ (here b > 4)
      }
      own_r = detail::arc_chord_deviation(psi);
      arc = std::hypot(m.distance(), rho_b) * df;
      turned += psi;
    }
    x_dev = std::max(x_dev, own_x + std::max(x_gaps[i], x_gaps[i + 1]));
    if (radius > 0.0) r_dev = std::max(r_dev, own_r + std::max(r_gaps[i], r_gaps[i + 1]));
    x_disp = std::max(x_disp, (centers[i] - x_start).norm() + arc);
  }
  out.deviation = x_dev + radius * r_dev;
  out.displacement = x_disp + radius * 2.0 * std::sin(0.5 * std::min(turned, M_PI));
  return out;
}

AdaptiveSamples adaptive_time_samples(const std::function<double(double, double)>& deviation_bound, double t0,
                                      double t1, double tolerance, double min_step) {
  assert(t0 <= t1 && tolerance > 0.0 && min_step > 0.0);
  AdaptiveSamples out{{t0}, 0.0};
  if (!(t1 > t0)) return out;
  // Depth-first on an explicit stack of intervals, right halves pushed first so that the
  // output comes out in increasing time.
  std::vector<std::pair<double, double>> stack{{t0, t1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const double bound = deviation_bound(a, b);
    if (bound <= tolerance || b - a <= min_step) {
      out.times.push_back(b);
      out.deviation = std::max(out.deviation, bound);
      continue;
    }
    const double m = 0.5 * (a + b);
    stack.emplace_back(m, b);
    stack.emplace_back(a, m);
  }
  out.times.back() = t1;
  return out;
}

}  // namespace reconfig::motion
