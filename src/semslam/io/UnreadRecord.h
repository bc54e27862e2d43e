#pragma once
// The one diagnosis of a pose-graph record that a reader does not read (G2oReader, ToroReader, IsamReader): when
// the record belongs to another format, the file was most likely given in the wrong format, and the message says
// which one to read it as; otherwise the record type is unknown. Each message ends with the records the reader
// does read:
//   unsupported record type '<tag>' in a[n] <file format> file: it is a[n] <other format> record; read the file as
//     <readAs> (<file format> records read here: <supported>)
//   unknown record type '<tag>' (<file format> records read here: <supported>)
// The first foreign format whose test accepts the tag is named. A reader's own unsupported records (3D, extensions)
// are diagnosed by the reader before it calls this.

#include <functional>
#include <string_view>
#include <vector>

#include "semslam/io/LineReader.h"

namespace semslam {

struct ForeignRecordFormat {
  std::string_view name;    ///< as the message names it: "TORO", "iSAM", "g2o", "TORO or iSAM"
  std::string_view readAs;  ///< the format to read the file as: "toro", "isam", "g2o", "toro or isam"
  std::function<bool(std::string_view tag)> isRecord;
};

/// g2o record types: VERTEX_*, EDGE_*, FIX.
bool isG2oRecordType(std::string_view tag);

/// Fails on `reader`'s current record, which the `fileFormat` reader does not read.
[[noreturn]] void failUnreadRecord(const LineReader& reader, std::string_view fileFormat, std::string_view supported,
                                   const std::vector<ForeignRecordFormat>& foreignFormats);

}  // namespace semslam
