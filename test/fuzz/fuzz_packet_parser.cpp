// libFuzzer target: the streaming packet parser and every robot-packet decoder on arbitrary
// bytes split at arbitrary points. Invariants: no crash/UB (ASan, UBSan), every packet
// delivered fits the count limit and survives a re-encode/re-parse round trip, the byte
// accounting never exceeds the input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/packet.h"
#include "amigobot_tracking/aria/sip.h"

using namespace amigobot_tracking::aria;

namespace {
void check(bool condition) {
  if (!condition) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  // First byte: chunk size for the split reads; second: the parser's count limit.
  const std::size_t chunk = 1 + data[0] % 64;
  const std::size_t limit = data[1] < 3 ? kMaxSpecCount : data[1];
  data += 2;
  size -= 2;
  PacketParser parser(limit);
  std::size_t delivered_bytes = 0;
  Packet packet;
  auto drain = [&] {
    while (parser.next(packet)) {
      check(packet.payload.size() + 3 <= limit);
      delivered_bytes += packet.payload.size() + 6;
      decodeSip(packet);
      decodeSync2(packet);
      decodeConfigPac(packet);
      intArgument(packet);
      stringArgument(packet);
      if (packet.payload.size() + 3 <= kMaxSpecCount) {
        PacketParser again;
        again.feed(encodePacket(packet.type, packet.payload));
        Packet copy;
        check(again.next(copy) && copy.type == packet.type && copy.payload == packet.payload);
      }
    }
  };
  for (std::size_t i = 0; i < size; i += chunk) {
    parser.feed(data + i, chunk < size - i ? chunk : size - i);
    drain();
  }
  for (int i = 0; i < 300 && parser.hasPartial(); ++i) {
    parser.expirePartial();
    drain();
  }
  check(!parser.hasPartial());
  check(delivered_bytes + parser.stats().garbage_bytes <= size);
  return 0;
}
