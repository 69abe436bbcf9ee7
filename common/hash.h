#pragma once

/// @file
/// The one content hash Cairn computes: 64-bit FNV-1a (with Cairn's offset basis, below). Files embed its values
/// (the transition oracle's payload checksum and the walking model's content hash in every oracle file), so it
/// must never change.

#include <cstdint>
#include <string>
#include <string_view>

namespace cairn {

/// The starting value of a new hash, and the hash of no bytes. NOTE: this is not FNV's published 64-bit offset
/// basis 14695981039346656037 but that number without its last digit, as Cairn's first two FNV-1a copies had it;
/// it is kept because oracle files already store hashes made with it (algorithm and prime are FNV-1a 64's).
inline constexpr std::uint64_t kFnv1a64OffsetBasis = 1469598103934665603ULL;

/// FNV-1a 64's prime.
inline constexpr std::uint64_t kFnv1a64Prime = 1099511628211ULL;

/// 64-bit FNV-1a of `bytes`, continuing from `hash`. Hashing pieces in turn, each from the previous result, gives
/// the hash of their concatenation: Fnv1a64(b, Fnv1a64(a)) == Fnv1a64(a + b). Not cryptographic: it detects
/// accidental changes (an edited model, a corrupt file), not deliberate ones.
std::uint64_t Fnv1a64(std::string_view bytes, std::uint64_t hash = kFnv1a64OffsetBasis);

/// `hash` as 16 lower-case hexadecimal digits with leading zeros, the way files write hashes.
std::string HashHex(std::uint64_t hash);

}  // namespace cairn
