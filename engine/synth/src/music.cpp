#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "platon/synth/synth.h"

namespace platon::synth {

std::vector<Note> parseNotes(const std::string& text) {
  std::vector<Note> notes;
  size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ' || text[i] == '\t' || text[i] == '\n') {
      ++i;
      continue;
    }
    const size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\n') ++i;
    const std::string token = text.substr(start, i - start);
    const auto bad = [&](const std::string& why) {
      throw std::invalid_argument("note '" + token + "' at character " + std::to_string(start + 1) + ": " + why);
    };
    if (token == "-") {
      if (notes.empty()) bad("a hold ('-') needs a note or rest before it");
      ++notes.back().steps;
      continue;
    }
    if (token == ".") {
      notes.push_back({-1, 1});
      continue;
    }
    static constexpr int kSemitones[] = {9, 11, 0, 2, 4, 5, 7};  // A B C D E F G
    const char name = token[0];
    if (name < 'A' || name > 'G') bad("expected a note A..G (with # or b and an octave 0..8), '-' or '.'");
    int pitch = kSemitones[name - 'A'];
    size_t k = 1;
    if (k < token.size() && (token[k] == '#' || token[k] == 'b')) pitch += token[k++] == '#' ? 1 : -1;
    if (k + 1 != token.size() || token[k] < '0' || token[k] > '8') bad("expected an octave 0..8 after the note's name");
    notes.push_back({12 * (token[k] - '0' + 1) + pitch, 1});
  }
  return notes;
}

MusicPlayer::MusicPlayer(Music music, int rate)
    : music_(std::move(music)),
      rate_(rate),
      samplesPerStep_(60.0 * rate / (music_.tempo * music_.stepsPerBeat)),
      states_(music_.voices.size()) {}

void MusicPlayer::mix(float* out, size_t frames, float gain) {
  for (size_t i = 0; i < frames; ++i) {
    float left = 0, right = 0;
    for (size_t v = 0; v < music_.voices.size(); ++v) {
      const Voice& voice = music_.voices[v];
      if (voice.notes.empty()) continue;
      VoiceState& s = states_[v];
      const Note& note = voice.notes[s.note];
      if (note.pitch < 0) continue;
      // Where in the note we are, in seconds from its start and to its end.
      const double sinceStart = (s.stepInNote * samplesPerStep_ + stepClock_) / rate_;
      const double toEnd = (note.steps * samplesPerStep_ - s.stepInNote * samplesPerStep_ - stepClock_) / rate_;
      double level = std::min(1.0, sinceStart / std::max(voice.attack, 0.001));
      level = std::min(level, std::max(0.0, toEnd / std::max(voice.release, 0.001)));
      if (voice.decay > 0) level *= std::exp(-sinceStart / voice.decay);
      const double f = 440.0 * std::pow(2.0, (note.pitch - 69) / 12.0);
      const double before = s.phase;
      s.phase += f / rate_;
      s.phase -= std::floor(s.phase);
      const bool newCycle = std::floor(s.phase * 16) != std::floor(before * 16);
      const float x = oscillator(voice.wave, s.phase, voice.duty, s.noise, s.noiseValue, newCycle) *
                      static_cast<float>(level * voice.volume);
      left += x * static_cast<float>(std::min(1.0, 1 - voice.pan));
      right += x * static_cast<float>(std::min(1.0, 1 + voice.pan));
    }
    out[2 * i] = std::clamp(out[2 * i] + left * gain, -1.0f, 1.0f);
    out[2 * i + 1] = std::clamp(out[2 * i + 1] + right * gain, -1.0f, 1.0f);
    // The next step: every voice moves on, to its next note when this one is done.
    if (++stepClock_ >= samplesPerStep_) {
      stepClock_ -= samplesPerStep_;
      for (size_t v = 0; v < music_.voices.size(); ++v) {
        const Voice& voice = music_.voices[v];
        if (voice.notes.empty()) continue;
        VoiceState& s = states_[v];
        if (++s.stepInNote >= voice.notes[s.note].steps) s.stepInNote = 0, s.note = (s.note + 1) % voice.notes.size();
      }
    }
  }
}

}  // namespace platon::synth
