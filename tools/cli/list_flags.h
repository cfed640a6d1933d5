#pragma once

// Comma-separated list flags ("a,b,c"): the one parser of items, numbers
// and integers the tools share.

#include <cstddef>
#include <string>
#include <vector>

namespace mlndt {
namespace tools {

// Splits "a,b,c" into items trimmed of blanks; false when the list or an
// item is empty (including a trailing comma).
bool SplitList(const std::string& text, std::vector<std::string>* items);

// Parses "a,b,c" into finite numbers; false when an item is not one,
// including empty items ("1,,2", a leading or a trailing comma). Spaces
// around a number are allowed. An empty text is an empty list (callers that
// need items check for it).
bool ParseNumberList(const std::string& text, std::vector<double>* values);

// Parses "a,b,c" into integers (SplitList items); false on anything else.
bool ParseIntList(const std::string& text, std::vector<int>* values);

// Parses "a,b,c" (SplitList items) into whole numbers in [min_value,
// max_value]: digits only, no sign, point or exponent, so "1e300" and
// 18446744073709551615 are refused, not wrapped or rounded. False with
// *error naming the bad item and the range.
bool ParseCountList(const std::string& text,
                    size_t min_value,
                    size_t max_value,
                    std::vector<size_t>* values,
                    std::string* error);

// Parses mlndt_scaling's --sizes: strictly increasing positive integers;
// false with *error naming the flag and the bad item.
bool ParseSizes(const std::string& text,
                std::vector<size_t>* sizes,
                std::string* error);

// "a.txt,b.tum" into file names as given (a name may hold blanks); false
// with *error naming `flag`=`text` ("--estimate=...") on an empty name.
bool SplitFileList(const std::string& flag,
                   const std::string& text,
                   std::vector<std::string>* files,
                   std::string* error);

// "100,200,..." into lengths [m] (mlndt_eval's KITTI segments); false with
// *error naming `flag`=`text` when one is not > 0 or is given twice.
bool ParseLengthList(const std::string& flag,
                     const std::string& text,
                     std::vector<double>* lengths,
                     std::string* error);

}  // namespace tools
}  // namespace mlndt
