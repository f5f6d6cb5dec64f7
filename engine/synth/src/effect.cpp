#include <algorithm>
#include <cmath>
#include <cstring>

#include "platon/synth/synth.h"

namespace platon::synth {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// A seed from the effect's own numbers, so two effects that differ only in noise still differ, and
// one effect sounds the same in every run.
uint32_t seedOf(const Effect& e) {
  uint32_t h = 2166136261u;
  const double fields[] = {e.frequency, e.slideTo, e.duty, e.attack, e.sustain, e.decay, e.volume};
  for (double f : fields) {
    unsigned char bytes[sizeof f];
    std::memcpy(bytes, &f, sizeof f);
    for (unsigned char b : bytes) h = (h ^ b) * 16777619u;
  }
  return h | 1u;
}

// Loudness at time t: a linear rise, a held part with a punch that fades over it, a linear fall.
double envelope(const Effect& e, double t) {
  const double attack = std::max(e.attack, 0.001);
  if (t < attack) return t / attack;
  t -= attack;
  if (t < e.sustain) return 1 + e.punch * (1 - t / e.sustain);
  t -= e.sustain;
  if (t < e.decay) return 1 - t / e.decay;
  return 0;
}

}  // namespace

float oscillator(Wave wave, double phase, double duty, uint32_t& noise, float& noiseValue, bool newCycle) {
  switch (wave) {
    case Wave::Square:
      // 1.2 from low to high (a square is loud: that matches the others' weight), its mean at 0 for
      // any duty, so a thin pulse carries no offset into the mix.
      return static_cast<float>(phase < duty ? 1.2 * (1 - duty) : -1.2 * duty);
    case Wave::Saw:
      return static_cast<float>(1 - 2 * phase);
    case Wave::Triangle:
      return static_cast<float>(phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase);
    case Wave::Sine:
      return static_cast<float>(std::sin(kTwoPi * phase));
    case Wave::Noise:
      if (newCycle) {
        noise ^= noise << 13, noise ^= noise >> 17, noise ^= noise << 5;  // xorshift32
        noiseValue = static_cast<float>(noise) / 2147483648.0f - 1.0f;
      }
      return noiseValue;
  }
  return 0;
}

double lengthOf(const Effect& e) { return std::max(e.attack, 0.001) + e.sustain + e.decay; }

std::vector<float> render(const Effect& e, int rate) {
  const double length = lengthOf(e);
  const size_t count = static_cast<size_t>(std::ceil(length * rate));
  std::vector<float> out(count);
  uint32_t noise = seedOf(e);
  float noiseValue = 0;
  double phase = 0, filtered = 0;
  const double smoothing = e.lowpass > 0 ? 1 - std::exp(-kTwoPi * e.lowpass / rate) : 1;
  const double slide = e.slideTo > 0 ? std::log(e.slideTo / e.frequency) : 0;
  const size_t fade = static_cast<size_t>(0.002 * rate);  // no click at the end
  // Noise changes value 16 times a cycle: a pitched hiss that slides like a tone.
  const double noiseSteps = e.wave == Wave::Noise ? 16 : 1;
  for (size_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(i) / rate;
    double f = e.frequency * std::exp(slide * t / length);
    if (e.vibratoDepth > 0) f *= 1 + e.vibratoDepth * std::sin(kTwoPi * e.vibratoRate * t);
    if (e.arpeggioAt > 0 && t >= e.arpeggioAt) f *= e.arpeggioRatio;
    const double before = phase * noiseSteps;
    phase += f / rate;
    phase -= std::floor(phase);
    const bool newCycle = std::floor(phase * noiseSteps) != std::floor(before) || i == 0;
    const double x = oscillator(e.wave, phase, e.duty, noise, noiseValue, newCycle);
    filtered += smoothing * (x - filtered);
    double v = filtered * envelope(e, t) * e.volume;
    if (count - i <= fade) v *= static_cast<double>(count - i) / static_cast<double>(fade);
    out[i] = static_cast<float>(std::clamp(v, -1.0, 1.0));
  }
  return out;
}

}  // namespace platon::synth
