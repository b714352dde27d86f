#include "amigobot_tracking/core/support/input_file.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace amigobot_tracking {
namespace core {
namespace {

std::string megabytes(std::uintmax_t bytes) {
  return std::to_string(bytes / 1000000) + "." + std::to_string(bytes / 100000 % 10) + " MB";
}

}  // namespace

std::string regularFileProblem(const std::string& path, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found) return "does not exist";
  if (error) return "cannot be examined (" + error.message() + ")";
  if (status.type() == fs::file_type::directory) return "is a directory, not a file";
  if (status.type() != fs::file_type::regular) return "is not a regular file (a device, FIFO or socket)";
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) return "cannot be examined (" + error.message() + ")";
  if (size > max_bytes) return "is " + megabytes(size) + ", more than the " + megabytes(max_bytes) + " accepted";
  return "";
}

std::string readInputFile(const std::string& path, std::uintmax_t max_bytes) {
  const std::string problem = regularFileProblem(path, max_bytes);
  if (!problem.empty()) throw std::runtime_error(path + ": " + problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be opened for reading");
  std::string text;
  char chunk[65536];
  // Bounded however the file changes between the check and the read.
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes) throw std::runtime_error(path + ": grew past " + megabytes(max_bytes) + " while read");
  }
  if (in.bad()) throw std::runtime_error(path + ": read error");
  return text;
}

}  // namespace core
}  // namespace amigobot_tracking
