#pragma once
/// \file
/// Small text helpers shared by the loaders and the reports.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gdpn::core {

/// Levenshtein distance between `a` and `b` (insertions, deletions, substitutions).
std::size_t editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word` if it is close enough to be a likely typo, else "".
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);

/// " (did you mean 'x'?)" when a close candidate exists, else "".
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

/// `n` and a regular noun in its number: "1 edge", "2 edges", "0 edges".
std::string counted(std::size_t n, std::string_view noun);

/// The shortest decimal text that reads back as exactly `value` ("0.1", "4", "1e-05"); a
/// negative zero is written "0" (a file or a log never says `-0`).
std::string formatDouble(double value);

/// The double a 32-bit value stands for: the one nearest the shortest decimal that reads back
/// as `value` as a float (0.6F gives 0.6, not 0.6000000238418579), so that what a 32-bit
/// source (a mesh file, a colour widget) says is written as it was typed.
double widenFloat(float value);

/// A model time in seconds as text, to the nanosecond and without the noise of its sum of
/// steps: 781 steps of 0.01 s print as "7.81", not "7.8100000000000005".
std::string formatTime(double seconds);

/// Writes `words` after text that ends at `column`, a space before each, wrapping lines at
/// 100 columns with `indent` spaces before the continuation; past `most` words, how many more
/// ("... and N more (--json lists all)").
void writeWrapped(std::ostream& out, std::size_t column, const std::vector<std::string_view>& words, std::size_t indent,
                  std::size_t most = static_cast<std::size_t>(-1));
/// writeWrapped() for words held as strings.
void writeWrapped(std::ostream& out, std::size_t column, const std::vector<std::string>& words, std::size_t indent,
                  std::size_t most = static_cast<std::size_t>(-1));

/// `text` split at its spaces.
std::vector<std::string_view> words(std::string_view text);

/// True for [A-Za-z_][A-Za-z0-9_]*.
bool isIdentifier(std::string_view s);

/// True for a word Python reserves (`class`, `None`, `lambda`): no attribute can be named so.
bool isPythonKeyword(std::string_view s);

/// The number `s` writes ("0.8", "-3", "1e-3"), all of it; nullopt for anything else
/// (blanks, trailing text, an empty string).
std::optional<double> parseNumber(std::string_view s);

}  // namespace gdpn::core

namespace gdpn::core {

/// `s` with the characters XML reserves (< > & ") written as entities, for text and
/// attribute values.
std::string xmlEscape(std::string_view s);

/// `s` as a JSON string literal, quotes included, with control characters escaped.
std::string jsonQuote(std::string_view s);

/// 64-bit FNV-1a hash of `data` (for pinning trace bytes in tests).
std::uint64_t fnv1a(std::string_view data);

}  // namespace gdpn::core

namespace gdpn::core {

/// Offset of the first byte that is not valid UTF-8 (overlongs and surrogates count as
/// invalid), or npos when all of `s` is valid.
std::size_t firstInvalidUtf8(std::string_view s);

/// `s` (a path, a message naming one) with every byte that is not part of valid UTF-8
/// written as `\xNN`, the rest as it is: a path in a folder of any bytes prints readably.
std::string escapeInvalidUtf8(std::string_view s);

/// `text` for a cell of a markdown table: each `|` (which would end the cell) escaped.
std::string markdownCell(std::string_view text);

/// 1-based line and column (in bytes) of `offset` in `text`.
std::pair<int, int> lineColumn(std::string_view text, std::size_t offset);

}  // namespace gdpn::core
