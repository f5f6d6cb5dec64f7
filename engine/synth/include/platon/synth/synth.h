// The game's sounds, made here from a few numbers each (sfxr's model: one oscillator, a pitch
// slide, an envelope, a low-pass filter), so every sound Platon ships is made by code in this
// repository and carries its licence. Effects are rendered once into samples; music is played by a
// step sequencer of a few voices that renders as it goes. Plain data and plain functions: no device,
// no files, nothing random that a seed does not fix.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace platon::synth {

enum class Wave : uint8_t { Square, Saw, Triangle, Sine, Noise };

// One short sound. Times in seconds, frequencies in Hz.
struct Effect {
  Wave wave = Wave::Square;
  double frequency = 440;   // at the start
  double slideTo = 0;       // at the end of the sound, along an exponential curve (0: no slide)
  double duty = 0.5;        // a square wave's high part, 0.05..0.95
  double attack = 0.005;    // rise to full loudness
  double sustain = 0.05;    // held at full loudness (plus `punch`, fading over the sustain)
  double punch = 0;         // extra loudness at the sustain's start, 0..1
  double decay = 0.1;       // fall to silence
  double vibratoDepth = 0;  // a fraction of the frequency
  double vibratoRate = 0;   // Hz
  double arpeggioAt = 0;    // the time the frequency jumps by arpeggioRatio (0: never)
  double arpeggioRatio = 1;
  double lowpass = 0;   // cutoff in Hz (0: none)
  double volume = 0.5;  // 0..1
};

// The samples of `effect` at `rate` per second, mono, within [-1, 1]. Deterministic: the noise
// comes from a generator seeded by the effect's own numbers.
std::vector<float> render(const Effect& effect, int rate);
// Its length in seconds.
double lengthOf(const Effect& effect);

// A note of a voice: a MIDI pitch (60 is middle C) held for `steps` steps; pitch < 0 is a rest.
struct Note {
  int pitch = -1;
  int steps = 1;
};

// One line of a tune, looped: an instrument and its notes.
struct Voice {
  Wave wave = Wave::Square;
  double duty = 0.5;
  double attack = 0.01;  // seconds, per note
  double release = 0.1;  // seconds of fade at each note's end
  double decay = 0;      // seconds for a note to fall to 1/e of its loudness (a pluck, a drum); 0: held
  double volume = 0.3;
  double pan = 0;  // -1 left .. 1 right
  std::vector<Note> notes;
};

// A tune: voices stepped together at `tempo` beats a minute, `stepsPerBeat` steps to a beat. Each
// voice loops over its own notes, so a short bass line under a long melody is written once.
struct Music {
  double tempo = 120;
  int stepsPerBeat = 4;
  std::vector<Voice> voices;
};

// Parses a voice's notes: tokens split by spaces, each a note ("C4", "F#3", "Bb5": name, an
// optional # or b, an octave 0..8), "-" (the previous note held one more step) or "." (a step of
// rest). Throws std::invalid_argument naming the token and its place (1-based character).
std::vector<Note> parseNotes(const std::string& text);

// Plays a tune into stereo frames, continuing where the last call stopped (the audio thread calls
// it; it allocates nothing after construction).
class MusicPlayer {
 public:
  MusicPlayer(Music music, int rate);
  // Adds `frames` stereo frames (left, right interleaved, within [-1, 1]) to `out`, times `gain`.
  void mix(float* out, size_t frames, float gain);
  const Music& music() const { return music_; }

 private:
  struct VoiceState {
    size_t note = 0;     // index in the voice's notes
    int stepInNote = 0;  // steps played of that note
    double phase = 0;    // oscillator phase, 0..1
    uint32_t noise = 0x1234567u;
    float noiseValue = 0;
  };
  Music music_;
  int rate_;
  double samplesPerStep_;
  double stepClock_ = 0;  // samples into the current step
  std::vector<VoiceState> states_;
};

// The sample of `wave` at `phase` (0..1). `noise` holds a noise generator's state.
float oscillator(Wave wave, double phase, double duty, uint32_t& noise, float& noiseValue, bool newCycle);

}  // namespace platon::synth
