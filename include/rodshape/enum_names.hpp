// enum_names.hpp: one table of names per enum, read both ways (Ceres' types.cc pattern): the
// enum's to_string() and the task reader's choices and parsing use the same table, so that a name
// is spelt once. A table lists every value once, in the enum's order.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace rodshape {

template <typename Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

template <typename Enum, std::size_t N>
using EnumNames = std::array<EnumName<Enum>, N>;

/// The name of `value` in `table`, or `otherwise` when the table lacks it (a value cast from an
/// integer).
template <typename Enum, std::size_t N>
constexpr std::string_view name_of(const EnumNames<Enum, N>& table,
                                   Enum value,
                                   std::string_view otherwise = "unknown") {
  for (const EnumName<Enum>& entry : table)
    if (entry.value == value) return entry.name;
  return otherwise;
}

/// The value named `name` in `table`, or nullopt.
template <typename Enum, std::size_t N>
constexpr std::optional<Enum> value_of(const EnumNames<Enum, N>& table, std::string_view name) {
  for (const EnumName<Enum>& entry : table)
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

/// Every name of `table`, in its order (a reader's choices).
template <typename Enum, std::size_t N>
std::vector<std::string_view> names_of(const EnumNames<Enum, N>& table) {
  std::vector<std::string_view> names;
  for (const EnumName<Enum>& entry : table) names.push_back(entry.name);
  return names;
}

}  // namespace rodshape
