#include "core/io/Base64.hpp"

#include <array>

namespace vorodg {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
constexpr int kPad = 64, kSpace = 65, kBad = 66;

constexpr std::array<unsigned char, 256> make_table() {
  std::array<unsigned char, 256> t{};
  for (auto& v : t) v = kBad;
  for (int i = 0; i < 64; ++i)
    t[static_cast<unsigned char>(kAlphabet[i])] = static_cast<unsigned char>(i);
  t['='] = kPad;
  for (unsigned char c : {' ', '\t', '\n', '\r'}) t[c] = kSpace;
  return t;
}
constexpr std::array<unsigned char, 256> kTable = make_table();

std::string describe(unsigned char c) {
  static const char* hex = "0123456789abcdef";
  if (c >= 0x21 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
  return std::string("byte 0x") + hex[c >> 4] + hex[c & 15];
}

}  // namespace

void base64_append(std::string_view bytes, std::string& out) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size();
  std::size_t at = out.size();
  out.resize(at + (n + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3) {
    const unsigned v = (p[i] << 16) | (p[i + 1] << 8) | p[i + 2];
    out[at++] = kAlphabet[v >> 18];
    out[at++] = kAlphabet[(v >> 12) & 63];
    out[at++] = kAlphabet[(v >> 6) & 63];
    out[at++] = kAlphabet[v & 63];
  }
  if (i < n) {
    const bool two = i + 1 < n;
    const unsigned v = (p[i] << 16) | (two ? p[i + 1] << 8 : 0);
    out[at++] = kAlphabet[v >> 18];
    out[at++] = kAlphabet[(v >> 12) & 63];
    out[at++] = two ? kAlphabet[(v >> 6) & 63] : '=';
    out[at++] = '=';
  }
}

bool Base64Decoder::next_group() {
  int value[4], count = 0;
  std::size_t start = pos_;
  while (count < 4 && pos_ < text_.size()) {
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    const int v = kTable[c];
    if (v == kSpace) {
      ++pos_;
      continue;
    }
    if (v == kBad) {
      error_ = "invalid base64 character " + describe(c) + " at character " + std::to_string(pos_);
      return false;
    }
    if (count == 0) start = pos_;
    value[count++] = v;
    ++pos_;
  }
  if (count == 0) return false;  // the end of the text
  if (count < 4) {
    error_ = "base64 text ends inside a group of 4 characters (at character " +
             std::to_string(start) + ")";
    return false;
  }
  // '=' only at the end of a group: "xx==" holds one byte, "xxx=" two.
  const bool bad_pad =
      value[0] == kPad || value[1] == kPad || (value[2] == kPad && value[3] != kPad);
  if (bad_pad) {
    error_ = "misplaced base64 padding '=' in the group at character " + std::to_string(start);
    return false;
  }
  const unsigned v = (value[0] << 18) | (value[1] << 12) | ((value[2] & 63) << 6) | (value[3] & 63);
  group_[0] = static_cast<unsigned char>(v >> 16);
  group_[1] = static_cast<unsigned char>(v >> 8);
  group_[2] = static_cast<unsigned char>(v);
  len_ = value[2] == kPad ? 1 : (value[3] == kPad ? 2 : 3);
  next_ = 0;
  return true;
}

std::size_t Base64Decoder::read(std::size_t n, std::string& out) {
  std::size_t done = 0;
  while (done < n) {
    if (next_ == len_ && !next_group()) break;
    while (next_ < len_ && done < n) {
      out.push_back(static_cast<char>(group_[next_++]));
      ++done;
    }
  }
  return done;
}

}  // namespace vorodg
