#include "codec.hpp"

#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

#include <cstring>
#include <memory>
#include <stdexcept>

#include "byte_io.hpp"

namespace plexus::mcap {

const char* compression_name(Compression c) {
  switch (c) {
    case Compression::zstd: return "zstd";
    case Compression::lz4: return "lz4";
    case Compression::none: break;
  }
  return "";
}

namespace detail {

uint32_t crc32_update(uint32_t crc, const void* p, std::size_t n) {
  const auto* b = static_cast<const Bytef*>(p);
  while (n > 0) {  // zlib takes a uInt length
    const auto step = static_cast<uInt>(std::min<std::size_t>(n, 1u << 30));
    crc = static_cast<uint32_t>(::crc32(crc, b, step));
    b += step;
    n -= step;
  }
  return crc;
}

void compress(Compression c, int zstd_level, void*& zstd_ctx, const unsigned char* src, std::size_t n,
              std::vector<unsigned char>& out) {
  switch (c) {
    case Compression::none: out.assign(src, src + n); return;
    case Compression::zstd: {
      if (!zstd_ctx) zstd_ctx = ZSTD_createCCtx();
      if (!zstd_ctx) throw std::bad_alloc();
      out.resize(ZSTD_compressBound(n));
      const std::size_t r =
          ZSTD_compressCCtx(static_cast<ZSTD_CCtx*>(zstd_ctx), out.data(), out.size(), src, n, zstd_level);
      if (ZSTD_isError(r)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(r));
      out.resize(r);
      return;
    }
    case Compression::lz4: {
      LZ4F_preferences_t prefs;
      std::memset(&prefs, 0, sizeof prefs);
      prefs.frameInfo.contentSize = n;  // readers can check the size before they decode
      out.resize(LZ4F_compressFrameBound(n, &prefs));
      const std::size_t r = LZ4F_compressFrame(out.data(), out.size(), src, n, &prefs);
      if (LZ4F_isError(r)) throw std::runtime_error(std::string("lz4: ") + LZ4F_getErrorName(r));
      out.resize(r);
      return;
    }
  }
}

void free_zstd(void* zstd_ctx) { ZSTD_freeCCtx(static_cast<ZSTD_CCtx*>(zstd_ctx)); }

void decompress(const std::string& compression, const unsigned char* src, std::size_t n, unsigned char* dst,
                std::size_t size) {
  if (compression.empty()) {
    if (n != size)
      throw FormatError("uncompressed chunk of " + std::to_string(n) + " bytes announces " + std::to_string(size), 0);
    if (n) std::memcpy(dst, src, n);
    return;
  }
  if (compression == "zstd") {
    const std::size_t r = ZSTD_decompress(dst, size, src, n);
    if (ZSTD_isError(r))
      throw FormatError(std::string("zstd chunk does not decompress (") + ZSTD_getErrorName(r) + ")", 0);
    if (r != size)
      throw FormatError("zstd chunk decompresses to " + std::to_string(r) + " bytes, not the " + std::to_string(size) +
                            " it announces",
                        0);
    return;
  }
  if (compression == "lz4") {
    LZ4F_dctx* raw = nullptr;
    if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION))) throw std::bad_alloc();
    const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> ctx(raw, LZ4F_freeDecompressionContext);
    std::size_t in = 0, out = 0;
    while (in < n) {  // one frame, or several one after the other
      std::size_t src_n = n - in, dst_n = size - out;
      const std::size_t r = LZ4F_decompress(raw, dst + out, &dst_n, src + in, &src_n, nullptr);
      if (LZ4F_isError(r))
        throw FormatError(std::string("lz4 chunk does not decompress (") + LZ4F_getErrorName(r) + ")", 0);
      in += src_n;
      out += dst_n;
      if (src_n == 0 && dst_n == 0)
        throw FormatError("lz4 chunk decompresses to more than the " + std::to_string(size) + " bytes it announces", 0);
      if (r != 0 && in == n) throw FormatError("lz4 chunk ends inside its frame", 0);
    }
    if (out != size)
      throw FormatError("lz4 chunk decompresses to " + std::to_string(out) + " bytes, not the " + std::to_string(size) +
                            " it announces",
                        0);
    return;
  }
  throw FormatError("chunk compression '" + compression + "' is not supported (zstd, lz4 or none)", 0);
}

}  // namespace detail
}  // namespace plexus::mcap
