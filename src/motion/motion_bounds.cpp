#include "reconfig/motion/motion_bounds.h"

#include "motion/detail/key_times.h"
#include "motion/detail/so3.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <utility>

namespace reconfig::motion {

using detail::KeyLocation;

namespace {

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

/// Shared bookkeeping: the part's center follows xc(t), its frame turns by R(t). [t0, t1] is
/// cut into pieces at the key times strictly inside it, and `eval` gives the path's value at
/// each breakpoint, once per breakpoint, without allocating. Each piece [a, b] bounds its own
/// chord deviation; the caller adds the (linear) difference between the piece chords and the
/// interval chord, measured at the breakpoints: per breakpoint, its `gap` from the interval's
/// chord, gap(value, value at t0, value at t1, w) with w the breakpoint's weight between t0
/// and t1 (a norm of value − ((1 − w) front + w back)); zero at t0 and t1, which the chord
/// passes through. Calls piece(a, b, value at a, gap at a, gap at b) in increasing time.
template <class Eval, class Gap, class Piece>
void for_each_piece(const std::vector<double>& key_times, double t0, double t1, Eval eval, Gap gap, Piece piece) {
  using Value = decltype(eval(t0));
  using Gaps = decltype(gap(std::declval<const Value&>(), std::declval<const Value&>(), std::declval<const Value&>(), 0.0));
  const Value front = eval(t0), back = eval(t1);
  const auto last = std::lower_bound(key_times.begin(), key_times.end(), t1);
  double a = t0;
  Value at_a = front;
  Gaps gap_a{};
  for (auto key = std::upper_bound(key_times.begin(), key_times.end(), t0);; ++key) {
    if (key >= last) {
      piece(a, t1, at_a, gap_a, Gaps{});
      return;
    }
    const double b = *key;
    Value at_b = eval(b);
    const Gaps gap_b = gap(at_b, front, back, lerp_weight(b, t0, t1));
    piece(a, b, at_a, gap_a, gap_b);
    a = b;
    at_a = std::move(at_b);
    gap_a = gap_b;
  }
}

/// |value − chord| for a center path, and ‖value − chord‖₂ for a frame path.
double center_gap(const Eigen::Vector3d& at, const Eigen::Vector3d& front, const Eigen::Vector3d& back, double w) {
  return Eigen::Vector3d(at - ((1 - w) * front + w * back)).norm();
}
double frame_gap(const Eigen::Matrix3d& at, const Eigen::Matrix3d& front, const Eigen::Matrix3d& back, double w) {
  return operator_norm(Eigen::Matrix3d(at - ((1 - w) * front + w * back)));
}

}  // namespace

MotionBound keyframed_motion_bound(const BezierTranslationTrack& translation,
                                   const SlerpRotationTrack& rotation, double radius, double t0,
                                   double t1) {
  assert(t0 <= t1 && radius >= 0.0);
  MotionBound out;
  if (!(t1 > t0)) return out;

  // Translation.
  const std::vector<double>& xt = translation.key_times();
  Eigen::Vector3d x_start;  // x(t0): the value at the first piece's start
  double x_dev = 0.0, x_disp = 0.0;
  for_each_piece(
      xt, t0, t1, [&](double t) { return translation.evaluate(t); }, center_gap,
      [&](double a, double b, const Eigen::Vector3d& x_a, double gap_a, double gap_b) {
        if (a == t0) x_start = x_a;
        const PieceSegment ps = piece_segment(xt, a, b);
        double own = 0.0;
        if (ps.moving) {
          const auto P = translation.control_points(ps.j);
          const std::array<Eigen::Vector3d, 4> Q = {
              blossom(P, ps.fa, ps.fa, ps.fa), blossom(P, ps.fa, ps.fa, ps.fb),
              blossom(P, ps.fa, ps.fb, ps.fb), blossom(P, ps.fb, ps.fb, ps.fb)};
          const double qa = (Q[1] - (2.0 * Q[0] + Q[3]) / 3.0).norm();
          const double qb = (Q[2] - (Q[0] + 2.0 * Q[3]) / 3.0).norm();
          own = cubic_hump_max(qa, qb);
          for (const Eigen::Vector3d& q : Q) x_disp = std::max(x_disp, (q - x_start).norm());
        } else {
          x_disp = std::max(x_disp, (x_a - x_start).norm());
        }
        x_dev = std::max(x_dev, own + std::max(gap_a, gap_b));
      });

  // Rotation.
  double r_dev = 0.0, turned = 0.0;
  if (radius > 0.0) {
    const std::vector<double>& rt = rotation.key_times();
    for_each_piece(
        rt, t0, t1, [&](double t) { return Eigen::Matrix3d(rotation.evaluate(t).toRotationMatrix()); }, frame_gap,
        [&](double a, double b, const Eigen::Matrix3d&, double gap_a, double gap_b) {
          const PieceSegment ps = piece_segment(rt, a, b);
          double own = 0.0;
          if (ps.moving) {
            const double psi = rotation.segment_rotation_vector(ps.j).norm() * (ps.fb - ps.fa);
            own = detail::arc_chord_deviation(psi);
            turned += psi;
          }
          r_dev = std::max(r_dev, own + std::max(gap_a, gap_b));
        });
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
  struct Place {
    Eigen::Vector3d center;
    Eigen::Matrix3d frame;
  };
  const auto place = [&](double t) {
    const Eigen::Isometry3d pose = track.at(t);
    return Place{pose * c, pose.linear()};
  };
  const auto gaps = [&](const Place& at, const Place& front, const Place& back, double w) {
    return std::array<double, 2>{center_gap(at.center, front.center, back.center, w),
                                 radius > 0.0 ? frame_gap(at.frame, front.frame, back.frame, w) : 0.0};
  };
  Eigen::Vector3d x_start;  // the center at t0: that of the first piece's start

  double x_dev = 0.0, r_dev = 0.0, x_disp = 0.0, turned = 0.0;
  for_each_piece(st, t0, t1, place, gaps, [&](double a, double b, const Place& at_a, const std::array<double, 2>& gap_a,
                                               const std::array<double, 2>& gap_b) {
    if (a == t0) x_start = at_a.center;
    const PieceSegment ps = piece_segment(st, a, b);
    double own_x = 0.0, own_r = 0.0, arc = 0.0;
    if (ps.moving) {
      const ScrewMotion& m = track.segment(ps.j);
      const double angle = m.angle(), df = ps.fb - ps.fa, psi = angle * df;
      const Eigen::Vector3d& s = m.axis();
      Eigen::Vector3d chord = m.end() * c - m.start() * c;
      const double along = chord.dot(s);
      chord -= along * s;
      const double ell = chord.norm();  // = 2 ρ sin(b/2)
      // b / sin(b/2) → 2 as b → 0.
      const double b_over_sin = angle == 0.0 ? 2.0 : angle / std::sin(0.5 * angle);
      const double rho_b = 0.5 * ell * b_over_sin;  // ρ b, the angular part of the speed
      if (psi * psi / 8.0 < 2.0) {
        own_x = rho_b * angle * df * df / 8.0;  // ρ ψ² / 8
      } else {
        own_x = ell / std::sin(0.5 * angle);  // 2ρ (here b > 4)
      }
      own_r = detail::arc_chord_deviation(psi);
      arc = std::hypot(m.distance(), rho_b) * df;
      turned += psi;
    }
    x_dev = std::max(x_dev, own_x + std::max(gap_a[0], gap_b[0]));
    if (radius > 0.0) r_dev = std::max(r_dev, own_r + std::max(gap_a[1], gap_b[1]));
    x_disp = std::max(x_disp, (at_a.center - x_start).norm() + arc);
  });
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
