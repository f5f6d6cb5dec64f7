// A bounce off a line inside a frame, exact for constant gravity.
//
// The frame would have ended at the contact point plus `remainingQ17`, with velocity `velocityQ16`
// (gravity `gravityQ16` per frame acting all along). Along the line's normal the body meets the
// line with speed s = sqrt(v_n^2 - 2 g_n r_n) (the frame's end velocity and remaining motion,
// normal parts) and tau = (v_n + s) / g_n of the frame left; it leaves with restitution * s.
// Nothing along the line changes. So the frame ends, as the exact motion would, with the velocity
// raised by (1 + restitution) s along the normal and the remaining motion by that times tau.
#pragma once
#include <optional>

#include "platon/physics/fraction.h"
#include "platon/physics/vec2.h"

namespace platon::physics {

enum class BounceOutcome {
  Bounces,  // velocityQ16 and remainingQ17 are the bounced ones
  Lands,    // it would leave slower than one frame of gravity brings it back: it lands instead
  NotYet,   // its exact motion, remainder included, does not reach the line in this frame (a
            // rounded step left it touching): no bounce yet, and nothing taken off its velocity
};

struct Bounce {
  BounceOutcome outcome = BounceOutcome::Lands;
  Vec2w velocityQ16;   // the frame's end velocity after the bounce
  Vec2w remainingQ17;  // the motion left after the contact, after the bounce
};

// `normal` points away from the line.
Bounce bounceOff(Vec2w velocityQ16, Vec2w gravityQ16, Vec2w remainingQ17, Vec2w normal, Fraction restitution);

}  // namespace platon::physics
