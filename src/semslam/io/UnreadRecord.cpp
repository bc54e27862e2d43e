#include "semslam/io/UnreadRecord.h"

#include <string>

#include "semslam/core/InputExcerpt.h"

namespace semslam {
namespace {

/// "a" or "an" before `name`, by its first letter: "an iSAM", "a TORO", "a g2o".
std::string withArticle(std::string_view name) {
  const bool vowel = !name.empty() && std::string_view("aeiouAEIOU").find(name.front()) != std::string_view::npos;
  return (vowel ? "an " : "a ") + std::string(name);
}

}  // namespace

bool isG2oRecordType(std::string_view tag) {
  return tag.substr(0, 7) == "VERTEX_" || tag.substr(0, 5) == "EDGE_" || tag == "FIX";
}

void failUnreadRecord(const LineReader& reader, std::string_view fileFormat, std::string_view supported,
                      const std::vector<ForeignRecordFormat>& foreignFormats) {
  const std::string tag(reader.tag());
  const std::string readHere = " (" + std::string(fileFormat) + " records read here: " + std::string(supported) + ")";
  for (const ForeignRecordFormat& foreign : foreignFormats) {
    if (foreign.isRecord(tag)) {
      reader.fail("unsupported record type '" + tag + "' in " + withArticle(fileFormat) + " file: it is " +
                  withArticle(foreign.name) + " record; read the file as " + std::string(foreign.readAs) + readHere);
    }
  }
  reader.fail("unknown record type '" + tag + "'" + readHere);
}

}  // namespace semslam
