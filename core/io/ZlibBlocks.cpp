#include "core/io/ZlibBlocks.hpp"

#include <zlib.h>

#include <new>
#include <stdexcept>
#include <vector>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

constexpr std::size_t kBlockSize = 32768;
// zlib's largest compression ratio is 1032:1; a header that claims more cannot be right (and must
// not make the reader allocate gigabytes for a few bytes of input).
constexpr std::uint64_t kMaxRatio = 1032, kRatioSlack = 64;

void put_word(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

std::string block_name(std::uint64_t k, std::uint64_t n) {
  return "zlib block " + std::to_string(k + 1) + " of " + std::to_string(n);
}

void inflate_block(const std::string& packed, std::size_t size, std::string& out,
                   const std::string& name) {
  const std::size_t at = out.size();
  out.resize(at + size);
  unsigned char spare = 0;  // zlib wants a buffer even for an empty block
  auto* dest = size ? reinterpret_cast<Bytef*>(&out[at]) : &spare;
  uLongf dest_len = static_cast<uLongf>(size);
  const int rc = uncompress(dest, &dest_len, reinterpret_cast<const Bytef*>(packed.data()),
                            static_cast<uLong>(packed.size()));
  if (rc == Z_BUF_ERROR && dest_len == size)
    throw InputError(name + " inflates to more than the " + std::to_string(size) +
                     " bytes the header announces");
  if (rc != Z_OK) throw InputError(name + " is not a valid zlib stream (" + zError(rc) + ")");
  if (dest_len != size)
    throw InputError(name + " inflates to " + std::to_string(dest_len) +
                     " bytes, the header says " + std::to_string(size));
}

/// The zlib streams of the 32 KiB blocks of `bytes`: one stream, reset between blocks (what
/// compress2 would do, without allocating its state for every block). Single-threaded on purpose:
/// on the shared 2-core machines here, OpenMP over blocks made a 1e5-cell write slower, not faster.
std::vector<std::string> compress_blocks(std::string_view bytes, BlockContent content) {
  const std::size_t n_blocks = (bytes.size() + kBlockSize - 1) / kBlockSize;
  std::vector<std::string> packed(n_blocks);
  z_stream zs{};
  const int strategy = content == BlockContent::reals ? Z_RLE : Z_DEFAULT_STRATEGY;
  if (deflateInit2(&zs, Z_BEST_SPEED, Z_DEFLATED, 15, 8, strategy) != Z_OK) throw std::bad_alloc();
  bool failed = false;
  for (std::size_t k = 0; k < n_blocks && !failed; ++k) {
    const std::string_view block = bytes.substr(k * kBlockSize, kBlockSize);
    deflateReset(&zs);
    packed[k].resize(deflateBound(&zs, static_cast<uLong>(block.size())));
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(block.data()));
    zs.avail_in = static_cast<uInt>(block.size());
    zs.next_out = reinterpret_cast<Bytef*>(packed[k].data());
    zs.avail_out = static_cast<uInt>(packed[k].size());
    failed = deflate(&zs, Z_FINISH) != Z_STREAM_END;  // cannot happen with deflateBound's room
    packed[k].resize(zs.total_out);
  }
  deflateEnd(&zs);
  if (failed) throw std::runtime_error("zlib could not compress a .vtu data array");
  return packed;
}

}  // namespace

ZlibBlocks deflate_vtk_blocks(std::string_view bytes, BlockContent content) {
  const std::vector<std::string> packed = compress_blocks(bytes, content);
  ZlibBlocks out;
  put_word(out.header, packed.size());
  put_word(out.header, kBlockSize);
  put_word(out.header, bytes.size() % kBlockSize);
  std::size_t total = 0;
  for (const std::string& p : packed) total += p.size();
  out.data.reserve(total);
  for (const std::string& p : packed) {
    put_word(out.header, p.size());
    out.data += p;
  }
  return out;
}

std::string inflate_vtk_blocks(VtuPayload& in, int header_bytes, bool big_endian) {
  const char* what = "the compression header";
  const std::uint64_t n = in.word(header_bytes, big_endian, what);
  if (n > in.max_bytes_left() / header_bytes)
    throw InputError("the compression header announces " + std::to_string(n) +
                     " blocks, more than the data can hold");
  const std::uint64_t block = in.word(header_bytes, big_endian, what);
  const std::uint64_t last = in.word(header_bytes, big_endian, what);
  if (n > 0 && (block == 0 || last > block))
    throw InputError("the compression header's block size " + std::to_string(block) +
                     " and last block size " + std::to_string(last) + " do not add up");
  std::vector<std::uint64_t> packed_sizes(n);
  for (auto& s : packed_sizes) s = in.word(header_bytes, big_endian, what);
  std::string out;
  std::string packed;
  for (std::uint64_t k = 0; k < n; ++k) {
    const std::uint64_t size = (k + 1 < n || last == 0) ? block : last;
    const std::string name = block_name(k, n);
    if (packed_sizes[k] > in.max_bytes_left() || size > kMaxRatio * packed_sizes[k] + kRatioSlack)
      throw InputError(name + ": the header's sizes do not add up (" +
                       std::to_string(packed_sizes[k]) + " compressed bytes for " +
                       std::to_string(size) + " bytes, " + std::to_string(in.max_bytes_left()) +
                       " bytes of data left at most)");
    packed.clear();
    in.read(packed_sizes[k], packed, name.c_str());
    inflate_block(packed, size, out, name);
  }
  return out;
}

}  // namespace vorodg
