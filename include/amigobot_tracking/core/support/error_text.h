// The message of a library's exception for a log line, a status or a diagnostic. MRPT's
// what() is a block: "==== MRPT exception ====", "Message: <the problem>", "Location: file:line
// [function]", "Call stack backtrace:" and one raw return address per frame ("[6 ]  0x7f53…"),
// each line ending in '\n'. Only the Message line names the problem; the addresses differ
// from run to run and mean nothing to a user. Every place that shows a library's exception
// text passes it through here (std only, so every layer can).
#pragma once

#include <cstddef>
#include <string>

namespace amigobot_tracking {
namespace core {

// MRPT's first non-empty "Message:" line when `what` has one; otherwise the first line that
// is not an MRPT header, location or backtrace frame. Trimmed; every byte outside printable
// ASCII becomes '?'; cut to max_chars (with "..."). "unknown error" when nothing is left.
std::string libraryMessage(const std::string& what, std::size_t max_chars = 240);

}  // namespace core
}  // namespace amigobot_tracking
