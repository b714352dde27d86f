// Shared by the libFuzzer targets: an invariant that aborts (libFuzzer records the input),
// and a scratch folder for the loaders that take a path (in /dev/shm when there is one).
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace fuzz_support {

inline void check(bool condition) {
  if (!condition) std::abort();
}

// A folder of this process, made once.
inline const std::string& scratchDir() {
  static const std::string dir = [] {
    const std::string base = ::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    std::string pattern = base + "/amigobot_fuzz_XXXXXX";
    if (::mkdtemp(&pattern[0]) == nullptr) std::abort();
    return pattern;
  }();
  return dir;
}

inline std::string writeScratch(const std::string& name, const std::string& bytes) {
  const std::string path = scratchDir() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

}  // namespace fuzz_support
