#pragma once
/// \file
/// Where in a JSON document parsing stopped, as the scene parser names fields ("blocks[0].max").
#include <string>
#include <string_view>

namespace tide::io {

/// The path of the value at which parsing `text` fails (e.g. a number beyond double:
/// "end_time", "blocks[1].min[2]"); empty when it parses or fails before the first value.
std::string jsonPathWhereParsingStops(std::string_view text);

}  // namespace tide::io
