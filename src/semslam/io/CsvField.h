#pragma once
// CsvField: a text as one CSV field (RFC 4180): as it is when it holds no comma, double quote, CR or LF; otherwise
// wrapped in double quotes with every double quote doubled. Python's csv module and every spreadsheet read it back
// unchanged.

#include <string>
#include <string_view>

namespace semslam {

std::string csvField(std::string_view text);

}  // namespace semslam
