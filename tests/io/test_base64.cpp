#include "sinew/io/base64.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io_test_support.hpp"

namespace sinew::io {
namespace {

// The test vectors of RFC 4648, section 10.
TEST(Base64, Rfc4648Vectors) {
  EXPECT_EQ(encode_base64(""), "");
  EXPECT_EQ(encode_base64("f"), "Zg==");
  EXPECT_EQ(encode_base64("fo"), "Zm8=");
  EXPECT_EQ(encode_base64("foo"), "Zm9v");
  EXPECT_EQ(encode_base64("foob"), "Zm9vYg==");
  EXPECT_EQ(encode_base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode_base64("foobar"), "Zm9vYmFy");
}

TEST(Base64, AllByteValuesRoundTripThroughTheTestDecoder) {
  std::string bytes;
  for (int i = 0; i < 256; ++i) bytes.push_back(static_cast<char>(i));
  for (std::size_t length = 0; length <= bytes.size(); length += 37) {
    const std::string input = bytes.substr(0, length);
    EXPECT_EQ(testing::decode_base64(encode_base64(input)), input) << "length " << length;
  }
  EXPECT_EQ(encode_base64("\xfb\xff"), "+/8=");
}

TEST(Base64, AppendKeepsWhatIsThere) {
  std::string out = "prefix:";
  const unsigned char data[] = {'f', 'o', 'o'};
  append_base64(out, data, sizeof(data));
  EXPECT_EQ(out, "prefix:Zm9v");
}

}  // namespace
}  // namespace sinew::io
