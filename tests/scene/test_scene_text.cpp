/// @file test_scene_text.cpp
/// Scene files that must be refused before parsing: too deeply nested, too large, or not a
/// regular file (a FIFO would block the reader forever).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "scene/scene_test_support.hpp"
#include "sinew/core/error.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/scene_text.hpp"

namespace sinew::scene {
namespace {

using ::testing::HasSubstr;
using testing::load_error;
using testing::TempDir;

std::string repeat(const std::string& piece, std::size_t count) {
  std::string text;
  text.reserve(piece.size() * count);
  for (std::size_t i = 0; i < count; ++i) text += piece;
  return text;
}

// Without the depth bound the parser's callback kept a path per open bracket: 100,000 levels
// took 36 s and 6.6 GB before std::bad_alloc. The scan stops at the 65th bracket.
TEST(SceneText, DeeplyNestedArraysAreRefusedAtTheFirstBracketTooDeep) {
  const TempDir directory;
  const std::string path = directory.write("deep.json", repeat("[", 100000));
  const std::string message = load_error(path);
  EXPECT_THAT(message, HasSubstr(path + ":1:65: JSON nested deeper than 64 levels"));
}

TEST(SceneText, DeeplyNestedObjectsAreRefusedWithLineAndColumn) {
  const TempDir directory;
  const std::string path = directory.write("deep.json", "\n" + repeat("{\"a\":", 100000));
  EXPECT_THAT(load_error(path), HasSubstr(path + ":2:321: JSON nested deeper than 64 levels"));
}

TEST(SceneText, BracketsInsideStringsDoNotCount) {
  // 100 brackets and an escaped quote inside a string: depth 1.
  const std::string text = "{\"name\": \"" + repeat("[{", 50) + "\\\"" + repeat("[", 10) + "\"}";
  EXPECT_NO_THROW(check_json_depth(text, 2, "scene.json"));
  EXPECT_NO_THROW(check_json_depth(repeat("[", 64) + repeat("]", 64), 64, "scene.json"));
  EXPECT_THROW(check_json_depth(repeat("[", 65), 64, "scene.json"), InputError);
  // Closing brackets bring the depth back down.
  EXPECT_NO_THROW(check_json_depth(repeat("[[]", 40), 64, "scene.json"));
}

TEST(SceneText, AFifoIsRefusedWithoutBeingOpened) {
  const TempDir directory;
  const std::string path = directory.file("scene.fifo");
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  // Opening the FIFO for reading would block until a writer appears: this returns only
  // because the file type is checked first.
  EXPECT_THAT(load_error(path), HasSubstr(path + ": is not a regular file (it is a FIFO (named pipe))"));
}

TEST(SceneText, ADirectoryIsRefused) {
  const TempDir directory;
  const std::string path = directory.file("scenes");
  std::filesystem::create_directories(path);
  EXPECT_THAT(load_error(path), HasSubstr(path + ": is not a regular file (it is a directory)"));
}

TEST(SceneText, AFileOverTheSizeLimitIsRefused) {
  const TempDir directory;
  const std::string path = directory.write("big.json", std::string(2000, ' ') + "{}");
  SceneTextLimits limits;
  limits.max_bytes = 1000;
  try {
    read_scene_text(path, limits);
    ADD_FAILURE() << "a 2002-byte file passed a 1000-byte limit";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("scene file too large (2002 bytes; the limit is 1000 bytes)"));
  }
  EXPECT_EQ(read_scene_text(path).size(), 2002u);
  // The default limit, 16 MiB, through load_scene_file.
  const std::string huge = directory.write("huge.json", std::string((16u << 20) + 1, ' '));
  EXPECT_THAT(load_error(huge), HasSubstr("scene file too large"));
}

}  // namespace
}  // namespace sinew::scene
