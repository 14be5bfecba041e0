#include "encode/gzip.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <string>

namespace linkage {
namespace {

// gzip's header (RFC 1952: 1f 8b, deflate, no name or time) and a round trip through zlib.
TEST(Gzip, IsGzipAndGivesTheDataBack) {
  std::string data;
  for (int i = 0; i < 5000; ++i) data += "frame " + std::to_string(i % 37) + "\n";
  const std::string packed = gzip(data);
  ASSERT_GE(packed.size(), 18u);
  EXPECT_EQ(static_cast<unsigned char>(packed[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(packed[1]), 0x8b);
  EXPECT_EQ(packed[2], 8);
  EXPECT_EQ(packed.substr(4, 4), std::string(4, '\0'));  // no time: the same data, the same bytes
  EXPECT_LT(packed.size(), data.size() / 10);
  EXPECT_EQ(gzip(data), packed);

  z_stream z{};
  ASSERT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
  std::string out(data.size() + 16, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
  z.avail_in = static_cast<uInt>(packed.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  inflateEnd(&z);
  EXPECT_EQ(out, data);
}

}  // namespace
}  // namespace linkage
