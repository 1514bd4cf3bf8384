#include "ossa/anim/turn.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/animator_params.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/step.h"
#include "ossa/anim/swing.h"

namespace ossa::anim {

namespace {

// A foot counts as in reach after the turn within this fraction of its leg's horizontal reach.
constexpr float kTurnReachUse = 0.95f;
// A leg stepping under its girdle after the turn lifts half a leg's length, over this many seconds.
constexpr float kTurnStepLiftOfLeg = 0.5f;
constexpr float kTurnStepSeconds = 0.3f;

}  // namespace

void turn_feet(const AnimContext& ctx, const SplinePrototypes& prototypes, const GaitState& gait, const BodyFrame& body,
               FootSet& feet) {
  const AnimRig& rig = ctx.rig;
  const int n = static_cast<int>(rig.girdles.size());
  // A foot hanging over a drop (step.h) turns back with the creature: it steps under its
  // girdle like any foot in the air (below).
  std::vector<char> was_air(feet.feet.size(), 0);
  for (size_t k = 0; k < feet.feet.size(); ++k) {
    FootState& f = feet.feet[k];
    if (!f.air) continue;
    was_air[k] = 1;
    unhang(f);
  }
  if (n > 0) {
    std::vector<int> old = feet.foot_of_leg;
    for (int g = 0; g < n; ++g) {
      const RigGirdle& mine = rig.girdles[g];
      const RigGirdle& other = rig.girdles[n - 1 - g];
      for (size_t k = 0; k < mine.legs.size(); ++k) {
        const int src = other.legs[std::min(k, other.legs.size() - 1)];
        feet.foot_of_leg[mine.legs[k]] = old[src];
      }
    }
    // Girdles of unequal size could map two legs to one foot; fall back to identity then.
    std::vector<int> seen(feet.feet.size(), 0);
    bool ok = true;
    for (int f : feet.foot_of_leg) ok &= (seen[f]++ == 0);
    if (!ok) feet.foot_of_leg = old;
  }
  const FootholdInputs in = planner(ctx, body, gait, feet);
  // A drop deeper than the legs climb back up, below every foot standing (below).
  const float climb = ctx.params.max_step_up * rig.climb_height;
  float lowest = INFINITY;
  for (const FootState& f : feet.feet) {
    if (f.state == LegState::kStance) lowest = std::min(lowest, f.pos_ws.y);
  }
  // Girdles spaced unevenly along the body (three leg pairs) cannot all land on feet: a leg
  // whose foot (standing or in the air) is now out of reach lifts from the nearest foot on the
  // ground it reaches and steps under its girdle. A foot in the air heading out of reach (to
  // where the body was going) steps under its girdle from where it is. A foot standing just
  // below a riser it faced, now behind it, steps too: the leg that takes it over comes down to
  // it from above and behind, and its shin would cut the step's edge (the knee clamp lifted the
  // 2 m-frame parasaurolophus turned on stairs.json until a forefoot stood 16 cm short).
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = feet.of_leg(leg);
    const RigLeg& info = rig.legs[i];
    const float h = rig.girdles[info.girdle].rest_height * ctx.params.stance_height;
    const float reach_x = kTurnReachUse * reach_across(info.contact_reach, h);
    const float joint_x = body.girdle_ws(rig, info.girdle).x;
    const bool foot_in_reach = std::fabs(f.pos_ws.x - joint_x) <= reach_x;
    if (!was_air[feet.foot_of_leg[i]] && foot_in_reach &&
        (f.state == LegState::kStance ? shin_clears_riser(in, leg, f.pos_ws) : std::fabs(f.to_ws.x - joint_x) <= reach_x)) {
      continue;
    }
    if (!foot_in_reach) {  // from the nearest foot on the ground in reach, else from where it is
      const FootState* from = nullptr;
      for (const FootState& other : feet.feet) {
        if (&other == &f || other.state != LegState::kStance || std::fabs(other.pos_ws.x - joint_x) > reach_x) continue;
        if (!from || std::fabs(other.pos_ws.x - joint_x) < std::fabs(from->pos_ws.x - joint_x)) from = &other;
      }
      if (from) f.pos_ws = from->pos_ws;
    }
    glm::vec2 landing;
    const bool found = find_landing(in, leg, f.pos_ws, joint_x, &landing);
    // A foot that hung over a drop and finds no ground its leg reaches from where the girdle
    // stands (the girdle is still over the drop) hangs on, tucked: stepping down the drop would
    // pull the body down after it, and a leg hanging stretched would drag its foot through the
    // ledge's face as the body walks back. So does any foot whose landing out of its leg's
    // reach lies down a drop deeper than the legs climb, below every foot standing (any, when
    // none stands): the creature turns away from the drop, not down it; one already half down
    // it, its forefeet on the floor below, steps on down as before. (A brachiosaurus, hip
    // 3.2 m, stopped at drops.json's 4 m ledge with a forefoot on its way down and the other
    // at the edge; turned round, those feet were its hind feet, their girdle over the drop, and
    // they stepped down to the floor below: the body, drawn down after them, put a rib 20 cm
    // into the ledge's corner.)
    const int k = feet.foot_of_leg[i];
    if ((was_air[k] || (found && landing.y < lowest - climb)) && (!found || !reaches(in, leg, landing))) {
      hang(ctx, body, leg, 0.0f, f);  // tucked: the girdle goes back over the ledge it hangs from
      // and it plants on that ledge once it meets it (it no longer steps off it: random 12
      // walked back from drops.json's pit on forefeet hanging along the top, and fell when its
      // hind feet stepped off the far side).
      f.floor = 1e30f;
      f.tucked = true;
      continue;
    }
    if (!found) landing = f.pos_ws;
    begin_swing(ctx, body, leg, f, landing, step_shape(prototypes, gait.run_factor, kTurnStepLiftOfLeg * info.reach, 1.0f / kTurnStepSeconds, true));
  }
  // Feet now point the other way: one that would reach into a step takes a quick step to the
  // nearest place it fits (already lifted on this tick).
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    FootState& f = feet.of_leg(leg);
    if (f.state != LegState::kStance || foot_fits(in, leg, f.pos_ws)) continue;
    glm::vec2 landing;
    if (nearest_fit(in, leg, f.pos_ws, &landing, true)) step_to(in, leg, f, landing);
  }
}

}  // namespace ossa::anim
