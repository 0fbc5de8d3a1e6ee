// did_you_mean.hpp (private to the io area): the allowed word closest to a misspelled one, for
// messages such as "rod.lenght: unknown key; did you mean 'length'?".
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rodshape::io_detail {

/// Optimal-string-alignment distance (Levenshtein plus transposition of two neighbours), ignoring
/// ASCII case: "lenght" is 1 from "length".
int edit_distance(std::string_view a, std::string_view b);

/// The candidate nearest to `word` if it is near enough to be a likely typo: distance ≤ 1 for words
/// of up to 3 letters, ≤ 2 up to 7 letters, ≤ 3 beyond. Ties go to the first candidate.
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string_view>& candidates);

/// "a, b, c": the candidates for an "expected one of" message.
std::string join_words(const std::vector<std::string_view>& words);

}  // namespace rodshape::io_detail
