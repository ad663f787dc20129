#pragma once
/// @file
/// Mutations for fuzzing the loaders: a valid file's bytes, changed a few times at random.

#include <random>
#include <string>
#include <vector>

namespace reconfig::testing {

/// `original` after 1–4 random edits: a random byte, a flipped bit, a truncation, a deleted or
/// duplicated range (up to `max_range` bytes), or one of `tokens` inserted or written over the
/// bytes there (tokens a parser finds interesting: separators, huge numbers, keywords).
std::string mutate_text(const std::string& original, std::mt19937& rng, const std::vector<std::string>& tokens,
                        std::size_t max_range = 64);

/// An integer setting of a fuzz campaign from the environment (RECONFIG_FUZZ_TRIALS,
/// RECONFIG_FUZZ_SEED), or `fallback` when it is not set.
int fuzz_setting(const char* name, int fallback);

}  // namespace reconfig::testing
