// The synthesizer: effects rendered the same every time, bounded, with no click at either end and
// no offset; notes parsed or refused with their place; music the same however the mixer's thread
// cuts its buffer.
#include "platon/synth/synth.h"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include <gtest/gtest.h>

using namespace platon::synth;

namespace {

double rms(const std::vector<float>& s) {
  double sum = 0;
  for (float v : s) sum += double(v) * v;
  return s.empty() ? 0 : std::sqrt(sum / double(s.size()));
}

// A family of effects: every wave, with slides up and down, punch, vibrato, arpeggio and filter.
std::vector<Effect> effects() {
  std::vector<Effect> out;
  for (Wave wave : {Wave::Square, Wave::Saw, Wave::Triangle, Wave::Sine, Wave::Noise})
    for (double slide : {0.0, 110.0, 1800.0})
      for (double lowpass : {0.0, 900.0}) {
        Effect e;
        e.wave = wave, e.frequency = 440, e.slideTo = slide, e.lowpass = lowpass, e.duty = 0.3;
        e.punch = 0.5, e.vibratoDepth = 0.05, e.vibratoRate = 9, e.arpeggioAt = 0.05, e.arpeggioRatio = 1.5;
        e.volume = 1;  // the loudest a bank may ask for
        out.push_back(e);
      }
  return out;
}

}  // namespace

TEST(Synth, EffectsAreTheSameEveryTimeBoundedAndAudible) {
  for (const Effect& e : effects()) {
    const std::vector<float> a = render(e, 44100), b = render(e, 44100);
    EXPECT_EQ(a, b);
    EXPECT_EQ(a.size(), static_cast<size_t>(std::ceil(lengthOf(e) * 44100)));
    for (float v : a) ASSERT_LE(std::fabs(v), 1.0f);
    EXPECT_GT(rms(a), 0.02) << int(e.wave);
  }
}

// A sound that starts or stops on a large sample clicks: each rises from silence and fades out.
TEST(Synth, EffectsStartAndEndInSilence) {
  for (const Effect& e : effects()) {
    const std::vector<float> s = render(e, 44100);
    EXPECT_LE(std::fabs(s.front()), 0.01f);
    EXPECT_LE(std::fabs(s.back()), 0.01f);
  }
}

// A thin pulse carries no offset into the mix, whatever its duty.
TEST(Synth, SquaresHaveNoOffsetAtAnyDuty) {
  for (double duty = 0.05; duty <= 0.951; duty += 0.1) {
    Effect e;
    e.wave = Wave::Square, e.frequency = 441, e.duty = duty, e.attack = 0, e.sustain = 1, e.decay = 0, e.volume = 1;
    const std::vector<float> s = render(e, 44100);
    const double mean = std::accumulate(s.begin(), s.end(), 0.0) / double(s.size());
    EXPECT_NEAR(mean, 0, 0.01) << duty;
  }
}

TEST(Synth, NoiseIsSeededByTheEffectsOwnNumbers) {
  Effect a;
  a.wave = Wave::Noise;
  Effect b = a;
  b.frequency = 441;
  EXPECT_EQ(render(a, 22050), render(a, 22050));
  EXPECT_NE(render(a, 22050), render(b, 22050));
}

TEST(Synth, NotesAreParsedAsMidiPitches) {
  const std::vector<Note> n = parseNotes("C4 - A4 . F#3 Bb5 - - C0\n  G8");
  ASSERT_EQ(n.size(), 7u);
  EXPECT_EQ(n[0].pitch, 60);
  EXPECT_EQ(n[0].steps, 2);
  EXPECT_EQ(n[1].pitch, 69);
  EXPECT_EQ(n[1].steps, 1);
  EXPECT_EQ(n[2].pitch, -1);
  EXPECT_EQ(n[3].pitch, 54);
  EXPECT_EQ(n[4].pitch, 82);
  EXPECT_EQ(n[4].steps, 3);
  EXPECT_EQ(n[5].pitch, 12);
  EXPECT_EQ(n[6].pitch, 115);
}

TEST(Synth, BadNotesAreRefusedWithTheirPlace) {
  const std::pair<const char*, const char*> cases[] = {
      {"C4 H4", "note 'H4' at character 4: expected a note A..G"},
      {"C4 C9", "note 'C9' at character 4: expected an octave 0..8"},
      {"C", "note 'C' at character 1: expected an octave"},
      {"- C4", "note '-' at character 1: a hold ('-') needs a note or rest before it"},
      {"C#", "note 'C#' at character 1: expected an octave"},
      {"c4", "note 'c4' at character 1: expected a note A..G"},
      {"C44", "note 'C44' at character 1: expected an octave"},
  };
  for (const auto& [text, error] : cases) {
    try {
      parseNotes(text);
      ADD_FAILURE() << text << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(error, 0), 0u) << e.what();
    }
  }
}

// The mixer's thread asks for buffers of any size: a tune is the same cut any way.
TEST(Synth, MusicIsTheSameHoweverItsBufferIsCut) {
  Music m;
  m.tempo = 150;
  Voice lead;
  lead.wave = Wave::Square, lead.decay = 0.2, lead.notes = parseNotes("C4 E4 - G4 . C5 - - B4");
  Voice drum;
  drum.wave = Wave::Noise, drum.decay = 0.03, drum.pan = 0.5, drum.notes = parseNotes("C6 . C6 C6");
  m.voices = {lead, drum};
  MusicPlayer whole(m, 22050), pieces(m, 22050);
  std::vector<float> a(2 * 22050, 0.0f), b(2 * 22050, 0.0f);
  whole.mix(a.data(), 22050, 0.8f);
  for (size_t done = 0, cut = 1; done < 22050; done += cut, cut = cut % 997 + 1) {
    cut = std::min(cut, 22050 - done);
    pieces.mix(b.data() + 2 * done, cut, 0.8f);
  }
  EXPECT_EQ(a, b);
  EXPECT_GT(rms(a), 0.02);
  // Panned right, the drum is louder on the right.
  double left = 0, right = 0;
  for (size_t i = 0; i < 22050; ++i) left += std::fabs(a[2 * i]), right += std::fabs(a[2 * i + 1]);
  EXPECT_GT(right, left);
}
