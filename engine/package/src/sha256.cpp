// SHA-256 through nettle (Debian's nettle-dev), as lower-case hex.
#include <nettle/sha2.h>

#include "platon/package/package.h"

namespace platon::package {

std::string sha256Hex(const std::string& bytes) {
  sha256_ctx context;
  sha256_init(&context);
  sha256_update(&context, bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()));
  uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&context, sizeof digest, digest);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const uint8_t b : digest) (out += kHex[b >> 4]) += kHex[b & 15];
  return out;
}

std::string manifestHash(const std::vector<PackageFile>& files) {
  std::string all;
  for (const PackageFile& f : files) all += f.path + '\0' + std::to_string(f.bytes) + '\0' + f.sha256 + '\n';
  return sha256Hex(all);
}

bool plainName(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.' || name[0] == '-') return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') return false;
  return name.find("..") == std::string::npos;
}

}  // namespace platon::package
