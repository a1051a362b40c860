// FNV-1a 64 gives the published test vectors, and a file's checksum is its bytes'.
#include "core/checksum.h"

#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>

TEST(Checksum, MatchesFnv1a64TestVectors) {
    EXPECT_EQ(engine::fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(engine::fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(engine::fnv1a64("foobar"), 0x85944171f73967e8ull);
    EXPECT_EQ(engine::checksumOf("a"), "fnv1a64:af63dc4c8601ec8c");
}

TEST(Checksum, FileChecksumIsItsBytesAndNamesAMissingFile) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "vox_checksum_test.bin";
    std::string bytes(200000, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = char(i * 7);  // more than one read buffer
    std::ofstream(file, std::ios::binary) << bytes;
    auto sum = engine::fileChecksum(file);
    ASSERT_TRUE(sum.ok()) << sum.error().message;
    EXPECT_EQ(*sum, engine::checksumOf(bytes));
    std::filesystem::remove(file);
    auto gone = engine::fileChecksum(file);
    ASSERT_FALSE(gone.ok());
    EXPECT_NE(gone.error().message.find("vox_checksum_test.bin: cannot read"), std::string::npos);
}
