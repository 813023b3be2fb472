#pragma once
/// \file
/// User data on scene nodes: named values a model declares (`data: {kind: red, order: 17}`) and
/// scripts read and set. One rule reads a datum written as text, for the model file, the IDE's
/// inspector and the replay alike.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gdpn/scene/types.h"

namespace gdpn::scene {

/// A node's user data, in the order each name was first set. A value is a bool, a whole
/// number, a number, a string or a list of numbers.
using UserData = std::vector<std::pair<std::string, FieldValue>>;

/// A datum written as plain text: `true` or `false` a bool, a whole decimal number an int, a
/// finite decimal number a double, numbers in brackets (`[1, 2.5]`) a list, anything else the
/// text itself.
[[nodiscard]] FieldValue datumFromText(std::string_view text);

/// A datum as text for people: numbers as the file writes them, a list in brackets, a string
/// as it is.
[[nodiscard]] std::string datumText(const FieldValue& value);

/// True when a string datum must be quoted to read back as text (it reads as a bool, a
/// number or a list, or is empty).
[[nodiscard]] bool datumNeedsQuotes(const std::string& text);

/// True when `value` is of a kind a datum can hold (not a 3- or 4-vector).
[[nodiscard]] bool isDatumKind(const FieldValue& value);

}  // namespace gdpn::scene
