#include "audio_system.h"

#include <SDL.h>
#include <SDL_mixer.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <vector>

namespace platon::audio {

// The opened device and what plays on it, shared by every audio system of the process.
struct Device {
  bool open = false;
  std::string silentBecause;  // why not open
  int rate = 44100;
  float musicVolume = 0.6f, effectsVolume = 0.9f;
  bool paused = false;
  // The tune: its name and player. The mixer's thread reads the player and the volumes under `lock`,
  // held by the game's thread only to swap a pointer or set a number.
  std::mutex lock;
  std::string tune;
  std::unique_ptr<synth::MusicPlayer> player;
  std::vector<float> scratch;
  int systems = 0;  // the audio systems alive (the game's thread only)
};

namespace {

// The mixer thread's music: the tune stepped into the device's buffer.
void playMusic(void* user, Uint8* stream, int bytes) {
  auto* device = static_cast<Device*>(user);
  const std::lock_guard<std::mutex> held(device->lock);
  const size_t frames = static_cast<size_t>(bytes) / (sizeof(int16_t) * 2);
  device->scratch.assign(frames * 2, 0.0f);
  if (device->player && !device->paused) device->player->mix(device->scratch.data(), frames, device->musicVolume);
  auto* out = reinterpret_cast<int16_t*>(stream);
  for (size_t i = 0; i < frames * 2; ++i) out[i] = static_cast<int16_t>(std::lround(device->scratch[i] * 32767.0f));
}

// Opened by the first audio system and kept for the rest of the process, like the plugin itself:
// closing costs a join of SDL's audio thread (about 50 ms) and quitting its subsystem another join
// (about 100 ms with ALSA), which a level change or the game's exit would pay for nothing.
Device& theDevice() {
  static Device* const device = [] {
    auto* d = new Device();  // never destroyed: the process's exit closes the device
    // A game without a sound card still plays: silent, and it says why.
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
      d->silentBecause = std::string("no audio: ") + SDL_GetError();
    } else if (Mix_OpenAudio(44100, AUDIO_S16SYS, 2, 1024) != 0) {
      d->silentBecause = std::string("no audio device: ") + Mix_GetError();
    } else {
      int frequency = 0, channels = 0;
      Uint16 format = 0;
      Mix_QuerySpec(&frequency, &format, &channels);
      d->rate = frequency;
      d->open = format == AUDIO_S16SYS && channels == 2;  // what the chunks and the music are made as
      if (!d->open) {
        d->silentBecause = "no audio: the device wants another sample format than 16-bit stereo";
      } else {
        Mix_AllocateChannels(24);
        Mix_MasterVolume(static_cast<int>(std::lround(d->effectsVolume * 128)));
        Mix_HookMusic(playMusic, d);
      }
    }
    if (!d->open) std::fprintf(stderr, "platon: %s; the game plays silent\n", d->silentBecause.c_str());
    return d;
  }();
  return *device;
}

}  // namespace

AudioSystem::AudioSystem(const core::SoundBank& bank) : device_(&theDevice()), bank_(bank) { ++device_->systems; }

AudioSystem::~AudioSystem() {
  for (auto& [name, kept] : chunks_) Mix_FreeChunk(kept.chunk);  // halts the channels playing it
  // The last scene that names audio is gone (the title with a level that does not): silence.
  if (--device_->systems == 0 && device_->open) {
    const std::lock_guard<std::mutex> held(device_->lock);
    device_->player.reset();
    device_->tune.clear();
  }
}

Mix_Chunk* AudioSystem::chunkOf(const std::string& name) {
  const auto cached = chunks_.find(name);
  if (cached != chunks_.end()) {
    uses_.splice(uses_.begin(), uses_, cached->second.use);  // the most recently played now
    return cached->second.chunk;
  }
  const auto effect = bank_.effects.find(name);
  if (effect == bank_.effects.end()) return nullptr;
  const double seconds = synth::lengthOf(effect->second);
  if (renderedThisFrame_ + seconds > kMaxRenderedSeconds) return nullptr;  // not heard this frame
  renderedThisFrame_ += seconds;
  // Rendered at the device's rate, as 16-bit stereo (the same on both sides: panning is the channel's).
  const std::vector<float> mono = synth::render(effect->second, device_->rate);
  std::vector<int16_t> stereo(mono.size() * 2);
  for (size_t i = 0; i < mono.size(); ++i)
    stereo[2 * i] = stereo[2 * i + 1] = static_cast<int16_t>(std::lround(mono[i] * 32767.0f));
  auto* bytes = static_cast<Uint8*>(SDL_malloc(stereo.size() * sizeof(int16_t)));
  if (!bytes) return nullptr;
  std::copy_n(reinterpret_cast<const Uint8*>(stereo.data()), stereo.size() * sizeof(int16_t), bytes);
  Mix_Chunk* chunk = Mix_QuickLoad_RAW(bytes, static_cast<Uint32>(stereo.size() * sizeof(int16_t)));
  if (!chunk) {
    SDL_free(bytes);
    return nullptr;
  }
  chunk->allocated = 1;  // Mix_FreeChunk frees the samples too
  keep(name, chunk);
  return chunk;
}

void AudioSystem::keep(const std::string& name, Mix_Chunk* chunk) {
  // The least recently played go first (never the one just made): freeing one halts its channels.
  while (!uses_.empty() && keptBytes_ + chunk->alen > kMaxKeptBytes) {
    const auto oldest = chunks_.find(uses_.back());
    keptBytes_ -= oldest->second.chunk->alen;
    Mix_FreeChunk(oldest->second.chunk);
    chunks_.erase(oldest);
    uses_.pop_back();
  }
  uses_.push_front(name);
  chunks_[name] = {chunk, uses_.begin()};
  keptBytes_ += chunk->alen;
}

void AudioSystem::playEffect(const std::string& name, float volume, float pan) {
  if (!device_->open || device_->paused) return;
  Mix_Chunk* chunk = chunkOf(name);
  if (!chunk) return;
  // A free channel, set up before it starts, so no sample plays at another sound's volume.
  const int channel = Mix_GroupAvailable(-1);
  if (channel < 0) return;  // every channel busy: the newest sound is the one dropped
  Mix_Volume(channel, static_cast<int>(
                          std::lround(std::clamp(volume, 0.0f, 1.0f) * 128)));  // the effects volume is the master's
  const float p = std::clamp(pan, -1.0f, 1.0f);
  Mix_SetPanning(channel, static_cast<Uint8>(std::lround(255 * std::min(1.0f, 1 - p))),
                 static_cast<Uint8>(std::lround(255 * std::min(1.0f, 1 + p))));
  Mix_PlayChannel(channel, chunk, 0);
}

void AudioSystem::hear(const core::SoundFrame& frame) {
  if (!device_->open) return;
  renderedThisFrame_ = 0;
  for (const core::SoundEvent& e : frame.effects) playEffect(e.name, e.volume, e.pan);
  setTune(frame.music, frame.bank);
}

void AudioSystem::setTune(const std::string& name, const core::SoundBank& bank) {
  if (!device_->open || name == device_->tune) return;
  std::unique_ptr<synth::MusicPlayer> next;
  const auto tune = bank.music.find(name);
  if (tune != bank.music.end()) next = std::make_unique<synth::MusicPlayer>(tune->second, device_->rate);
  {
    const std::lock_guard<std::mutex> held(device_->lock);
    device_->player.swap(next);
  }
  device_->tune = name;
}

void AudioSystem::playTune(const std::string& name) { setTune(name, bank_); }

void AudioSystem::setVolumes(float music, float effects) {
  {
    const std::lock_guard<std::mutex> held(device_->lock);
    device_->musicVolume = std::clamp(music, 0.0f, 1.0f);
    device_->effectsVolume = std::clamp(effects, 0.0f, 1.0f);
  }
  // Every channel's, those playing now too (the tune's is read by the mixer thread above).
  if (device_->open) Mix_MasterVolume(static_cast<int>(std::lround(device_->effectsVolume * 128)));
}

void AudioSystem::setPaused(bool paused) {
  if (!device_->open || paused == device_->paused) return;
  {
    const std::lock_guard<std::mutex> held(device_->lock);
    device_->paused = paused;
  }
  if (paused)
    Mix_Pause(-1);
  else
    Mix_Resume(-1);
}

void AudioSystem::playNow(const std::string& name) {
  if (!device_->open) return;
  const bool paused = device_->paused;
  device_->paused = false;  // a menu's click sounds while the game is paused
  renderedThisFrame_ = 0;   // the game's own sound, not a frame's
  playEffect(name, 1, 0);
  device_->paused = paused;
}

std::string AudioSystem::silentBecause() const { return device_->silentBecause; }

}  // namespace platon::audio
