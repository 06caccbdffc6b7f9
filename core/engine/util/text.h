#pragma once

#include <string>

namespace sylva {

/// \p text with ASCII letters in lower case (file extensions and format sniffing: locale-free).
std::string lowerAscii(std::string text);

/// The shortest decimal that reads back as \p value ("0.3", "1e+05"; std::to_chars).
std::string shortestDecimal(double value);
std::string shortestDecimal(float value);

/// A float as the double of its shortest decimal: 0.3f becomes 0.3, not the double
/// 0.30000001192092896 it widens to, so a file written from floats reads as its own text
/// (the project's numbers, glTF's JSON).
double decimalOf(float value);

} // namespace sylva
