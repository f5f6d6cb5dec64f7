// The sound bank's reader: data files (lua_data.h) of named effects and tunes, read into
// engine/synth's types. docs/sound.md documents the fields.
#include <mutex>
#include <stdexcept>

#include "data_fields.h"
#include "platon/core/data_root.h"
#include "platon/core/sound.h"
#include "platon/files/read_file.h"

namespace platon::core {
namespace {

synth::Wave waveField(const std::string& file, const DataValue& table, synth::Wave fallback) {
  const DataValue* v = table.field("wave");
  if (!v) return fallback;
  static constexpr std::pair<const char*, synth::Wave> kWaves[] = {{"square", synth::Wave::Square},
                                                                   {"saw", synth::Wave::Saw},
                                                                   {"triangle", synth::Wave::Triangle},
                                                                   {"sine", synth::Wave::Sine},
                                                                   {"noise", synth::Wave::Noise}};
  if (v->isString())
    for (const auto& [name, wave] : kWaves)
      if (v->text == name) return wave;
  fieldError(file, *v,
             "'wave' must be \"square\", \"saw\", \"triangle\", \"sine\" or \"noise\", not " + describeData(*v));
}

// A name a script plays by: lower-case letters, digits and '_', 1 to 32 of them.
void checkName(const std::string& file, const DataEntry& e, const char* what) {
  bool ok = e.key.isString() && !e.key.text.empty() && e.key.text.size() <= 32;
  for (char c : e.key.text) ok = ok && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_');
  if (!ok)
    fieldError(
        file, e.key.line ? e.key : e.value,
        std::string(what) + " names are 1 to 32 of a-z, 0-9 and _ (jump, door_slam), not " + describeData(e.key));
  if (!e.value.isTable()) fieldError(file, e.value, std::string("'") + e.key.text + "' must be a table of fields");
}

synth::Effect readEffect(const std::string& file, const DataValue& t) {
  checkKeys(file, t,
            {"wave", "frequency", "slide_to", "duty", "attack", "sustain", "punch", "decay", "vibrato_depth",
             "vibrato_rate", "arpeggio_at", "arpeggio_ratio", "lowpass", "volume"});
  synth::Effect e;
  e.wave = waveField(file, t, e.wave);
  e.frequency = numberField(file, t, "frequency", e.frequency, 20, 20000);
  e.slideTo = numberField(file, t, "slide_to", 0, 0, 20000);
  if (e.slideTo != 0 && e.slideTo < 20)
    fieldError(file, *t.field("slide_to"), "'slide_to' must be 0 (none) or 20..20000 Hz");
  e.duty = numberField(file, t, "duty", e.duty, 0.05, 0.95);
  e.attack = numberField(file, t, "attack", e.attack, 0, 2);
  e.sustain = numberField(file, t, "sustain", e.sustain, 0, 4);
  e.punch = numberField(file, t, "punch", e.punch, 0, 1);
  e.decay = numberField(file, t, "decay", e.decay, 0, 4);
  e.vibratoDepth = numberField(file, t, "vibrato_depth", 0, 0, 0.5);
  e.vibratoRate = numberField(file, t, "vibrato_rate", 0, 0, 100);
  e.arpeggioAt = numberField(file, t, "arpeggio_at", 0, 0, 4);
  e.arpeggioRatio = numberField(file, t, "arpeggio_ratio", 1, 0.25, 4);
  e.lowpass = numberField(file, t, "lowpass", 0, 0, 20000);
  e.volume = numberField(file, t, "volume", e.volume, 0, 1);
  return e;
}

synth::Music readMusic(const std::string& file, const DataValue& t) {
  checkKeys(file, t, {"tempo", "steps_per_beat", "voices"});
  synth::Music m;
  m.tempo = numberField(file, t, "tempo", m.tempo, 20, 400);
  m.stepsPerBeat = static_cast<int>(wholeField(file, t, "steps_per_beat", m.stepsPerBeat, 1, 16));
  const DataValue* voices = t.field("voices");
  if (!voices || !voices->isTable() || voices->entries.empty() || voices->entries.size() > 8)
    fieldError(file, voices ? *voices : t,
               "'voices' must be a list of 1 to 8 voices { wave =, notes = \"C4 - E4 .\" }");
  for (const DataEntry& e : voices->entries) {
    const DataValue& v = e.value;
    if (!v.isTable()) fieldError(file, v, "a voice is a table { wave =, notes = \"C4 - E4 .\", ... }");
    checkKeys(file, v, {"wave", "duty", "attack", "release", "decay", "volume", "pan", "notes"});
    synth::Voice voice;
    voice.wave = waveField(file, v, voice.wave);
    voice.duty = numberField(file, v, "duty", voice.duty, 0.05, 0.95);
    voice.attack = numberField(file, v, "attack", voice.attack, 0, 2);
    voice.release = numberField(file, v, "release", voice.release, 0, 2);
    voice.decay = numberField(file, v, "decay", voice.decay, 0, 10);
    voice.volume = numberField(file, v, "volume", voice.volume, 0, 1);
    voice.pan = numberField(file, v, "pan", voice.pan, -1, 1);
    const DataValue* notes = v.field("notes");
    if (!notes || !notes->isString())
      fieldError(file, notes ? *notes : v, "a voice's 'notes' is a string: \"C4 - E4 .\"");
    try {
      voice.notes = synth::parseNotes(notes->text);
    } catch (const std::invalid_argument& error) {
      fieldError(file, *notes, error.what());
    }
    if (voice.notes.empty() || voice.notes.size() > 4096)
      fieldError(file, *notes, "a voice has 1 to 4096 notes and rests");
    m.voices.push_back(std::move(voice));
  }
  return m;
}

}  // namespace

void readSoundBank(const std::string& path, SoundBank& bank) {
  std::string text;
  try {
    text = files::readBoundedFile(path, kMaxSoundBankBytes);
  } catch (const files::FileError& e) {
    throw std::runtime_error(path + ": the sound bank: " + e.reason());
  }
  const DataValue root = readLuaData(text, path);
  if (!root.isTable()) fieldError(path, root, "a sound bank is a table: return { effects = { ... }, music = { ... } }");
  checkKeys(path, root, {"effects", "music"});
  if (const DataValue* effects = root.field("effects")) {
    if (!effects->isTable()) fieldError(path, *effects, "'effects' must be a table { name = { ... }, ... }");
    for (const DataEntry& e : effects->entries) {
      checkName(path, e, "effect");
      bank.effects[e.key.text] = readEffect(path, e.value);
    }
  }
  if (const DataValue* music = root.field("music")) {
    if (!music->isTable()) fieldError(path, *music, "'music' must be a table { name = { ... }, ... }");
    for (const DataEntry& e : music->entries) {
      checkName(path, e, "tune");
      bank.music[e.key.text] = readMusic(path, e.value);
    }
  }
}

const SoundBank& engineSoundBank() {
  // Read once: every scene of a run shares it. A damaged engine bank is the install's fault; it is
  // reported by the first scene that asks, every time it asks.
  static std::once_flag once;
  static SoundBank bank;
  static std::string error;
  std::call_once(once, [] {
    try {
      readSoundBank(engineFile("sounds/bank.lua"), bank);
    } catch (const std::exception& e) {
      error = e.what();
    }
  });
  if (!error.empty()) throw std::runtime_error(error);
  return bank;
}

}  // namespace platon::core
