#pragma once
// Turning round [T 4.4.1, 5.1]: a command against the facing mirrors the creature in place.
// The feet keep their world positions; leg pairs take over the feet standing where their
// girdle will be (girdle i ← girdle n-1-i, same side), and the root shifts so the front and
// back girdles land on each other's feet. A leg whose foot is then out of reach steps under
// its girdle; a foot that would reach into a step takes a quick step to where it fits.
//
// In/out: the body frame (x, facing, lean) and the feet; the body takes its new height and
// pitch at once on this tick (body placement's `snap`).

#include "ossa/anim/anim_state.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/spline_prototypes.h"

namespace ossa::anim {

void turn_round(const AnimContext& ctx, const SplinePrototypes& prototypes, float run_factor, float stride, float duty,
                BodyFrame& body, FootSet& feet);

}  // namespace ossa::anim
