#pragma once
/// @file
/// The leaf narrow phase: two triangles (leaves of the two trees of a pair timeline) over one
/// proxy step, or over a range of steps in which both parts hold still. Over a step the
/// triangles are culled by their k-DOPs per eighth of it (`meeting_pieces`) and by the groups
/// found so far, then tested exactly (`triangle_pair_ccd`), what only touches within δ is left
/// out (`interference_pieces`), and the runs of pieces left become contacts clipped to frames.
/// A clearance traversal (`DetectorOptions::closer_than`) asks `triangles_closer_than` instead.

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <span>
#include <vector>

#include "collision/detail/box_grid.h"
#include "collision/detail/moving_bounds.h"
#include "collision/detail/work_item.h"
#include "reconfig/collision/triangle_clearance.h"
#include "reconfig/collision/triangle_pair_ccd.h"
#include "reconfig/collision/triangle_touching.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::collision::detail {

/// The narrow phase of one leaf pair over samples [s0, s1] of its pair timeline, adding the
/// contacts found to the item context.
template <DopFamily family>
class LeafNarrowPhase {
 public:
  LeafNarrowPhase(const TraversalInputs<family>& inputs, const ItemContext& context, int pair, int leaf_a, int leaf_b,
                  int s0, int s1)
      : inputs_(inputs), context_(context), pair_(pair), line_(inputs.lines[pair]),
        step_(WorkItem{pair, leaf_a, leaf_b, s0, s1}),
        triangle_a_(inputs.tree(pair, 0).node(leaf_a).triangle), triangle_b_(inputs.tree(pair, 1).node(leaf_b).triangle),
        growth_a_(inputs.growth(pair, 0)), growth_b_(inputs.growth(pair, 1)),
        t0_(line_.times[s0]), t1_(line_.times[s1]) {
    const auto frames = item_frames(inputs, step_);
    first_frame_ = frames.first;
    last_frame_ = frames.second;
  }

  /// Over one step ([s0, s1] with s1 = s0 + 1) in which the triangles move linearly.
  void search_moving_step() {
    const int s0 = step_.s0, s1 = step_.s1;
    const MovingTriangle a0 = inputs_.triangle_at(pair_, 0, triangle_a_, s0);
    const MovingTriangle a1 = inputs_.triangle_at(pair_, 0, triangle_a_, s1);
    const MovingTriangle b0 = inputs_.triangle_at(pair_, 1, triangle_b_, s0);
    const MovingTriangle b1 = inputs_.triangle_at(pair_, 1, triangle_b_, s1);
    DetectionStats& stats = context_.stats;
    const auto box_between = [&](double ta, double tb) {
      const double mu0 = ta <= t0_ ? 0.0 : mu_at(ta), mu1 = tb >= t1_ ? 1.0 : mu_at(tb);
      return inflated(triangle_box_at(a0, a1, mu0, mu1), growth_a_ + inputs_.pad)
          .intersection(inflated(triangle_box_at(b0, b1, mu0, mu1), growth_b_ + inputs_.pad));
    };
    const unsigned meeting = meeting_pieces<family>(a0, a1, b0, b1, growth_a_ + growth_b_ + 2 * inputs_.pad);
    if (meeting == 0) return;
    // Contacts can only lie within the pieces where the triangles may meet.
    const double from = time_at(static_cast<double>(std::countr_zero(meeting)) / kCullPieces);
    const double to = time_at(static_cast<double>(std::bit_width(meeting)) / kCullPieces);
    if (protrusion(inputs_, step_, context_, box_between, from, to, kAnyProtrusion) == 0) {
      ++stats.pruned;
      return;
    }
    ++stats.narrow_phase;
    if (inputs_.options.closer_than > 0) return search_closer_than(a0, a1, b0, b1, meeting, box_between);
    TrianglePairCcdRequest request;
    request.a_start = a0;
    request.a_end = a1;
    request.b_start = b0;
    request.b_end = b1;
    request.time_tolerance = 1.0 / kNarrowPieces;  // of the step: pieces with a contact event are reported whole below that
    request.distance_tolerance = 1e-4;
    // The pieces come back unmerged, and a contact's box is the union of its pieces'
    // (`add_contacts_of_run`), so that what a piece adds does not depend on the pieces next to
    // it; then the pieces of the step where whatever the triangles meet in would fall inside
    // the groups can be left out. (Not in conservative mode: there the absence of contacts
    // matters too.)
    request.merge_pieces = false;
    if (!inputs_.options.conservative)
      request.relevant = [&](double lo, double hi) {
        return protrusion(inputs_, step_, context_, box_between, time_at(lo), time_at(hi), kAnyProtrusion) > 0;
      };
    const TrianglePairCcdResult spans = triangle_pair_ccd(request);
    stats.narrow_pieces += spans.pieces;
    stats.contact_tests += spans.contact_tests;
    // Where the triangles only touch within δ, they do not collide (`triangle_touching.h`).
    const std::vector<TimeInterval> pieces =
        inputs_.options.touching_collides ? spans.intervals : interference_pieces(a0, a1, b0, b1, spans.intervals, inputs_.contact);
    for (std::size_t first = 0, end = 1; first < pieces.size(); first = end++) {
      while (end < pieces.size() && pieces[end].lo <= pieces[end - 1].hi) ++end;  // a run of touching pieces
      add_contacts_of_run(a0, a1, b0, b1, std::span(pieces).subspan(first, end - first), false);
    }
    if (!spans.any() && inputs_.options.conservative) add_possible_contacts(a0, a1, b0, b1);
  }

  /// Over a range in which both parts hold still: one static test decides.
  void search_still_range() {
    ++context_.stats.narrow_phase;
    const MovingTriangle a = inputs_.triangle_at(pair_, 0, triangle_a_, step_.s0);
    const MovingTriangle b = inputs_.triangle_at(pair_, 1, triangle_b_, step_.s0);
    if (inputs_.options.closer_than > 0) {
      if (geometry::triangle_distance(a, b) < closer_than() + inputs_.pad) add_contacts_of_piece(a, a, b, b, 0, 1, false);
      return;
    }
    if (geometry::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]) &&
        (inputs_.options.touching_collides || !triangles_touch(a, b, inputs_.contact)))
      add_contacts_of_piece(a, a, b, b, 0, 1, false);
  }

 private:
  /// The distance a clearance traversal looks for: `closer_than`, plus the proxies'
  /// deviations in conservative mode (what the bounds grow by on both sides).
  double closer_than() const { return growth_a_ + growth_b_; }

  /// The clearance traversal's narrow phase over the step: the runs of pieces where the
  /// triangles may come closer than `closer_than()`, within the eighths of the step where
  /// their grown k-DOPs meet (`meeting`) and, unless conservative, where what they could
  /// meet in sticks out of the groups found so far.
  void search_closer_than(const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                          const MovingTriangle& b1, unsigned meeting, const auto& box_between) {
    TriangleClearanceRequest request;
    request.a_start = a0;
    request.a_end = a1;
    request.b_start = b0;
    request.b_end = b1;
    request.clearance = closer_than();
    request.rounding = inputs_.pad;
    request.time_tolerance = 1.0 / kNarrowPieces;
    request.relevant = [&](double lo, double hi) {
      const int first = static_cast<int>(std::floor(lo * kCullPieces));
      const int last = std::min(kCullPieces - 1, static_cast<int>(std::ceil(hi * kCullPieces)) - 1);
      const unsigned eighths = ((2u << last) - 1) & ~((1u << first) - 1);
      if ((meeting & eighths) == 0) return false;
      return inputs_.options.conservative ||
             protrusion(inputs_, step_, context_, box_between, time_at(lo), time_at(hi), kAnyProtrusion) > 0;
    };
    const TriangleClearanceResult near = triangles_closer_than(request);
    context_.stats.narrow_pieces += near.pieces;
    const std::vector<TimeInterval>& pieces = near.intervals;
    for (std::size_t first = 0, end = 1; first < pieces.size(); first = end++) {
      while (end < pieces.size() && pieces[end].lo <= pieces[end - 1].hi) ++end;  // a run of touching pieces
      add_contacts_of_run(a0, a1, b0, b1, std::span(pieces).subspan(first, end - first), false);
    }
  }

  double time_at(double mu) const { return mu == 0 ? t0_ : mu == 1 ? t1_ : t0_ + mu * (t1_ - t0_); }
  double mu_at(double t) const { return (t - t0_) / (t1_ - t0_); }

  /// The proxies miss, but the true motions stray up to the deviations from them: adds, as
  /// possible contacts, the sixteenths of the step where the triangles' spacetime k-DOPs, so
  /// inflated, meet.
  void add_possible_contacts(const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                             const MovingTriangle& b1) {
    const double reach = growth_a_ + growth_b_ + inputs_.pad;
    constexpr int kPieces = 16;
    for (int k = 0; k < kPieces; ++k) {
      const double lo = static_cast<double>(k) / kPieces, hi = static_cast<double>(k + 1) / kPieces;
      Kdop<family> dop_a, dop_b;
      for (double mu : {lo, hi})
        for (int c = 0; c < 3; ++c) {
          dop_a.extend((1 - mu) * a0[c] + mu * a1[c], mu);
          dop_b.extend((1 - mu) * b0[c] + mu * b1[c], mu);
        }
      dop_a.inflate(reach);
      if (dop_a.overlaps(dop_b)) add_contacts_of_piece(a0, a1, b0, b1, lo, hi, true);
    }
  }

  /// Where the triangles (or, for a possible contact, the true motions within the deviations;
  /// in a clearance traversal, the triangles grown by half the distance looked for) may meet
  /// over step parameters [mu_lo, mu_hi]; nowhere if the boxes miss each other there, which
  /// happens where a piece reported whole is clipped to a frame. The padding absorbs the
  /// rounding of the boxes.
  Eigen::AlignedBox3d meeting_box(const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                                  const MovingTriangle& b1, double mu_lo, double mu_hi, bool possible) const {
    const bool grown = possible || inputs_.options.closer_than > 0;
    const double grow_a = (grown ? growth_a_ : 0.0) + inputs_.pad, grow_b = (grown ? growth_b_ : 0.0) + inputs_.pad;
    const Eigen::AlignedBox3d box_a = triangle_box_at(a0, a1, mu_lo, mu_hi);
    const Eigen::AlignedBox3d box_b = triangle_box_at(b0, b1, mu_lo, mu_hi);
    Eigen::AlignedBox3d box = grown ? Eigen::AlignedBox3d() : box_a.intersection(box_b);
    if (box.isEmpty()) box = inflated(box_a, grow_a).intersection(inflated(box_b, grow_b));
    return box;
  }

  void add_contacts_of_piece(const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                             const MovingTriangle& b1, double mu0, double mu1, bool possible) {
    const TimeInterval piece{mu0, mu1};
    add_contacts_of_run(a0, a1, b0, b1, std::span(&piece, 1), possible);
  }

  /// Adds, as one contact per frame, a run of touching pieces of the step (step parameters) in
  /// which the triangles intersect: its time clipped to the frame, and the union over its
  /// pieces of where the triangles may meet during each (the box where they meet over a union
  /// of pieces would be larger, and depend on which pieces are reported).
  void add_contacts_of_run(const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                           const MovingTriangle& b1, std::span<const TimeInterval> run, bool possible) {
    const double ta = time_at(run.front().lo), tb = time_at(run.back().hi);
    if (ta == tb) {
      const int k = inputs_.grid.frame_of(ta);
      if (k >= first_frame_ && k <= last_frame_) add_contact_within_frame(a0, a1, b0, b1, run, possible, ta, ta);
      return;
    }
    const auto [f0, f1] = inputs_.grid.frames_overlapping(ta, tb);
    for (int k = std::max(f0, first_frame_); k <= std::min(f1, last_frame_); ++k) {
      const double lo = std::max(ta, inputs_.grid.lo(k)), hi = std::min(tb, inputs_.grid.hi(k));
      if (hi > lo) add_contact_within_frame(a0, a1, b0, b1, run, possible, lo, hi);
    }
  }

  /// The run's contact over [lo, hi] (within one frame and the run).
  void add_contact_within_frame(const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                                const MovingTriangle& b1, std::span<const TimeInterval> run, bool possible, double lo,
                                double hi) {
    Eigen::AlignedBox3d box;
    for (const TimeInterval& piece : run) {
      const double p_lo = time_at(piece.lo), p_hi = time_at(piece.hi);
      if (p_hi < lo || p_lo > hi) continue;
      box.extend(meeting_box(a0, a1, b0, b1, p_lo < lo ? mu_at(lo) : piece.lo, p_hi > hi ? mu_at(hi) : piece.hi, possible));
    }
    if (box.isEmpty()) return;
    context_.contacts.push_back({pair_,
                                 {line_.a, triangle_a_, line_.b, triangle_b_, lo, hi, round_out(box, inputs_.cell(pair_)),
                                  possible, t0_, t1_}});
  }

  const TraversalInputs<family>& inputs_;
  const ItemContext& context_;
  int pair_;
  const PairTimeline& line_;
  WorkItem step_;  ///< the leaf pair over [s0, s1]
  int triangle_a_, triangle_b_;
  double growth_a_, growth_b_;
  double t0_, t1_;  ///< the times of samples s0 and s1
  int first_frame_ = 0, last_frame_ = 0;  ///< the frames the range may report contacts in (`item_frames`)
};

}  // namespace reconfig::collision::detail
