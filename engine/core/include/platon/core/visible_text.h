// Text from a file or a script, fit to show in a message, on a terminal or in an XML report.
#pragma once
#include <string>
#include <string_view>

namespace platon::core {

// `text` with every byte that would hide or garble something shown as \xNN: control bytes (a NUL
// would end a C string, an escape would drive a terminal) but the tab, and line breaks unless
// `keepLineBreaks`, DEL, and bytes that are not valid UTF-8. Nothing is lost: valid UTF-8 passes.
std::string visibleText(std::string_view text, bool keepLineBreaks = false);

}  // namespace platon::core
