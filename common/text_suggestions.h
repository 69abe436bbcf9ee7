#pragma once

#include <string>
#include <vector>

namespace cairn {

/// Edit (Levenshtein) distance between two strings, for "did you mean" suggestions.
int EditDistance(const std::string& a, const std::string& b);

/// Returns up to `max_count` of `candidates` closest to `name` by edit distance (ties keep the candidates'
/// order), for error messages about unknown names.
std::vector<std::string> ClosestNames(const std::string& name, const std::vector<std::string>& candidates,
                                      int max_count = 3);

/// Joins strings as "'a', 'b', 'c'" for error messages.
std::string QuotedList(const std::vector<std::string>& items);

}  // namespace cairn
