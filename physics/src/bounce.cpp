#include "bounce.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>

#include "fixed_point.h"

namespace platon::physics {
namespace {

// The normal's direction in small integers: exact for lines of small slopes (divided by the gcd),
// within 2^-15 of it otherwise, so that the products below fit in 128 bits.
Vec2w smallNormal(Vec2w n) {
  const int64_t g = std::gcd(n.x, n.y);
  if (g > 1) n = {n.x / g, n.y / g};
  while (std::max(std::abs(n.x), std::abs(n.y)) > (int64_t{1} << 15)) n = {n.x / 2, n.y / 2};
  return n;
}

bool overflows(i128 a, i128 b, i128& product) { return __builtin_mul_overflow(a, b, &product); }

}  // namespace

Bounce bounceOff(Vec2w v, Vec2w g, Vec2w r, Vec2w normal, Fraction restitution) {
  const Vec2w n = smallNormal(normal);
  const i128 nn = dot128(n, n);
  if (restitution <= Fraction::zero() || nn == 0) return {};
  // Everything below is scaled by |n|: vn = v_n |n|, and so on. s^2 |n|^2 = vn^2 - gn rn in Q32
  // (Q16 gravity times Q17 motion is twice the Q32 product, which the 2 in 2 g_n r_n cancels).
  // At the ends of the legal range the products may not fit: then all three inputs lose bits
  // together (s scales with them), which costs precision only where speeds reach 2^40 units.
  int shift = 0;
  i128 vn = dot128(v, n), gn = dot128(g, n), rn = dot128(r, n), v2, gr;
  // Only a motion that reaches the line bounces. (A body that rounding left touching it, whose
  // exact position, remainder included, is still above it and rising, only lands.)
  if (rn >= 0) return {BounceOutcome::NotYet, v, r};
  while (overflows(vn, vn, v2) || overflows(gn, rn, gr) || v2 - gr < -(i128{1} << 126) || v2 > (i128{1} << 125) ||
         gr > (i128{1} << 125) || gr < -(i128{1} << 125)) {
    vn /= 4, gn /= 4, rn /= 4;
    shift += 2;
  }
  const i128 s2 = v2 - gr;
  if (s2 <= 0) return {};
  const i128 s = static_cast<i128>(isqrt(static_cast<u128>(s2)));  // s |n|, Q16, scaled down by 2^shift
  // Leaving slower than one frame of gravity brings back: a landing, not a bounce.
  if (i128{restitution.num} * s <= i128{restitution.den} * (gn < 0 ? -gn : gn)) return {};
  // The part of the frame left after the contact, Q30, within [0, 1].
  i128 tauQ30 = gn != 0 ? floorDiv((vn + s) << kQ30Bits, gn) : floorDiv(-rn << (kQ30Bits - 1), s);
  tauQ30 = std::clamp<i128>(tauQ30, 0, i128{1} << kQ30Bits);
  Bounce out{BounceOutcome::Bounces, v, r};
  for (int k = 0; k < 2; ++k) {
    const int64_t nk = k == 0 ? n.x : n.y;
    // (1 + e) s along the unit normal, Q16: s |n| n_k / |n|^2, times (num + den) / den.
    const i128 along = roundDiv((s << shift) * nk, nn);
    // Held to twice the largest velocity: any more is clamped away below anyway, and it keeps
    // dr in range for restitutions up to the largest fraction.
    const i128 dvLimit = i128{kMaxMove} << 17;
    const i128 dv = std::clamp<i128>(roundDiv(along * (i128{restitution.num} + restitution.den), restitution.den),
                                     -dvLimit, dvLimit);
    const i128 dr = roundDiv(2 * dv * tauQ30, i128{1} << kQ30Bits);  // Q16 per frame times frames, in Q17
    (k == 0 ? out.velocityQ16.x : out.velocityQ16.y) += static_cast<int64_t>(dv);
    (k == 0 ? out.remainingQ17.x : out.remainingQ17.y) += static_cast<int64_t>(dr);
  }
  out.velocityQ16 = clampVelocityQ16(out.velocityQ16);
  out.remainingQ17 = clampMotionQ17(out.remainingQ17);
  return out;
}

}  // namespace platon::physics
