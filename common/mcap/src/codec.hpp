// Chunk compression (zstd, LZ4 frames) and the CRC-32 MCAP uses (zlib's) (internal).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "plexus/mcap/records.hpp"

namespace plexus::mcap::detail {

/// CRC-32 (IEEE 802.3, as zlib's crc32) of [p, p + n), continuing from `crc` (0 to start).
uint32_t crc32_update(uint32_t crc, const void* p, std::size_t n);

/// The largest chunk plexus reads: a chunk announcing more uncompressed bytes is refused
/// (a corrupt size field must not allocate gigabytes).
inline constexpr uint64_t kMaxChunkBytes = 256ull << 20;

/// Compresses [src, src + n) into `out` (replaced). `zstd_ctx`: a ZSTD_CCtx* reused across
/// calls (created on first use; free it with free_zstd).
void compress(Compression c, int zstd_level, void*& zstd_ctx, const unsigned char* src, std::size_t n,
              std::vector<unsigned char>& out);
void free_zstd(void* zstd_ctx);

/// Decompresses [src, src + n), compressed as `compression` names it ("", "zstd", "lz4"),
/// into exactly `size` bytes at `dst`. FormatError (offset 0: the caller adds its own)
/// for an unknown compression, bytes that do not decode, or another size.
void decompress(const std::string& compression, const unsigned char* src, std::size_t n, unsigned char* dst,
                std::size_t size);

}  // namespace plexus::mcap::detail
