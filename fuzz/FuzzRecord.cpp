// libFuzzer target: records of the planning (mms-record/1) for a one-robot scene, and the round
// trip through the writer: an accepted record, written and read again, writes the same text.
// Same rules as FuzzScene.cpp.
#include <cstdint>
#include <string>

#include "FuzzSupport.h"
#include "io/Json.h"
#include "io/RecordIO.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  const std::string text(reinterpret_cast<const char*>(data), size);
  RecordFile f;
  try {
    f = parseRecord(json_in::parseText(text, "fuzz.json"), "fuzz.json", 1);
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.json: ");
    return 0;
  }
  // What the writer writes, the reader takes, and writes again the same.
  const std::string once = recordText(f.record, f.stats);
  const RecordFile again = parseRecord(json_in::parseText(once, "again"), "again", 1);
  fuzz::require(recordText(again.record, again.stats) == once,
                "a record written and read back writes other text");
  return 0;
}
