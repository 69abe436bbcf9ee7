#pragma once

/// @file
/// Internal: function multiversioning for the module's hot kernels. Not part of the installed API.

// The hot kernels are compiled twice (AVX2 and baseline x86-64) and picked at load time, so a generic build still
// uses the wide registers of the machine it runs on. Both versions compute the same IEEE operations (no FMA
// contraction across versions is introduced by the vectoriser for these loops), so results do not depend on the
// version picked.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CAIRN_MULTIVERSION __attribute__((target_clones("avx2", "default")))
#else
#define CAIRN_MULTIVERSION
#endif
