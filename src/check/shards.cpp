#include "check/shards.h"

#include <cstdio>
#include <stdexcept>

namespace raycam::check {

namespace {
constexpr int kMaxShards = 10000;
}

Shard parse_shard(const std::string& text, const std::string& flag) {
  Shard shard;
  int consumed = 0;
  const bool parsed = std::sscanf(text.c_str(), "%d/%d%n", &shard.index, &shard.count, &consumed) == 2 &&
                      consumed == int(text.size()) && text.find_first_of(" +-") == std::string::npos;
  if (!parsed || shard.count < 1 || shard.count > kMaxShards || shard.index < 1 || shard.index > shard.count)
    throw std::invalid_argument(flag + ": expected i/N with 1 <= i <= N <= " + std::to_string(kMaxShards) +
                                ", got '" + text + "'");
  return shard;
}

std::string shard_text(const Shard& shard) { return std::to_string(shard.index) + "/" + std::to_string(shard.count); }

std::uint64_t fnv1a_64(const std::string& bytes) {
  std::uint64_t hash = 14695981039346656037ull;  // the offset basis
  for (unsigned char byte : bytes) {
    hash ^= byte;
    hash *= 1099511628211ull;  // the 64-bit FNV prime
  }
  return hash;
}

int shard_of(const std::string& name, int count) { return int(fnv1a_64(name) % std::uint64_t(count)) + 1; }

}  // namespace raycam::check
