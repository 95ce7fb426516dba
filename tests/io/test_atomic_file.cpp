#include "sinew/io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "io_test_support.hpp"
#include "sinew/core/error.hpp"

namespace sinew::io {
namespace {

namespace fs = std::filesystem;
using testing::directory_entries;
using testing::read_text;
using testing::TempDir;

TEST(AtomicFile, ContentRoundTripsIncludingBinaryBytes) {
  TempDir scratch;
  std::string content = "first line\nsecond line\n";
  content.push_back('\0');
  content += "\xff\x01 after a NUL byte";
  const std::string path = scratch.file("out.bin");
  write_file_atomically(path, content);
  EXPECT_EQ(read_text(path), content);
  EXPECT_EQ(directory_entries(scratch.path()), std::vector<std::string>{"out.bin"});
}

TEST(AtomicFile, EmptyContentMakesAnEmptyFile) {
  TempDir scratch;
  const std::string path = scratch.file("empty.txt");
  write_file_atomically(path, "");
  ASSERT_TRUE(fs::exists(path));
  EXPECT_EQ(fs::file_size(path), 0u);
}

TEST(AtomicFile, ReplacesAnExistingFile) {
  TempDir scratch;
  const std::string path = scratch.file("table.csv");
  write_file_atomically(path, "a much longer old content that must disappear entirely\n");
  write_file_atomically(path, "new\n");
  EXPECT_EQ(read_text(path), "new\n");
  EXPECT_EQ(directory_entries(scratch.path()), std::vector<std::string>{"table.csv"});
}

TEST(AtomicFile, CreatesMissingParentDirectories) {
  TempDir scratch;
  const std::string path = scratch.file("a/b/c/out.txt");
  write_file_atomically(path, "deep");
  EXPECT_EQ(read_text(path), "deep");
}

TEST(AtomicFile, ParentIsARegularFileFailsNamingThePathAndLeavesNothingBehind) {
  TempDir scratch;
  const std::string blocker = scratch.file("not_a_directory");
  std::ofstream(blocker) << "I am a file";
  const std::string path = blocker + "/out.txt";
  try {
    write_file_atomically(path, "content");
    FAIL() << "expected sinew::Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    // The system's reason is part of the message (ENOTDIR or EEXIST depending on the call).
    EXPECT_TRUE(message.find("Not a directory") != std::string::npos ||
                message.find("exists") != std::string::npos)
        << message;
  }
  EXPECT_EQ(read_text(blocker), "I am a file");
  EXPECT_EQ(directory_entries(scratch.path()), std::vector<std::string>{"not_a_directory"});
}

// Works as root too (permissions would not): rename() cannot replace a non-empty directory.
TEST(AtomicFile, FailedRenameLeavesTheExistingTargetUnchangedAndRemovesTheTemporaryFile) {
  TempDir scratch;
  const std::string target = scratch.file("target");
  fs::create_directories(target);
  std::ofstream(target + "/keep.txt") << "kept";
  try {
    write_file_atomically(target, "content");
    FAIL() << "expected sinew::Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(target), std::string::npos) << message;
    EXPECT_NE(message.find("Is a directory"), std::string::npos) << message;
  }
  ASSERT_TRUE(fs::is_directory(target));
  EXPECT_EQ(read_text(target + "/keep.txt"), "kept");
  EXPECT_EQ(directory_entries(scratch.path()), std::vector<std::string>{"target"});
}

TEST(AtomicFile, PathWithoutAFileNameIsAnError) {
  TempDir scratch;
  EXPECT_THROW(write_file_atomically(scratch.path().string() + "/", "x"), Error);
  EXPECT_THROW(write_file_atomically("", "x"), Error);
}

// Concurrent writers each produce a whole file: readers only ever see one writer's content.
TEST(AtomicFile, ConcurrentWritersNeverInterleave) {
  TempDir scratch;
  const std::string path = scratch.file("shared.txt");
  const std::string content_a(100000, 'a');
  const std::string content_b(100000, 'b');
  std::thread writer_a([&] { for (int i = 0; i < 20; ++i) write_file_atomically(path, content_a); });
  std::thread writer_b([&] { for (int i = 0; i < 20; ++i) write_file_atomically(path, content_b); });
  for (int i = 0; i < 50; ++i) {
    if (!fs::exists(path)) continue;
    const std::string seen = read_text(path);
    EXPECT_TRUE(seen == content_a || seen == content_b) << "size " << seen.size();
  }
  writer_a.join();
  writer_b.join();
  const std::string final_content = read_text(path);
  EXPECT_TRUE(final_content == content_a || final_content == content_b);
  EXPECT_EQ(directory_entries(scratch.path()), std::vector<std::string>{"shared.txt"});
}

}  // namespace
}  // namespace sinew::io
