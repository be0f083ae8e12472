// The key tables of docs/scenes.md and the fuzz dictionary are generated from the scene reader's
// key tables: the committed files must be exactly what the tables give today.

#include "tide/io/scene_key_reference.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace tide::io {
namespace {

const std::filesystem::path source_dir = TIDE_SOURCE_DIR;

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  EXPECT_TRUE(in) << "cannot read " << file;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SceneKeyReference, TheScenesPageShowsTheTables) {
  const std::string page = read_file(source_dir / "docs/scenes.md");
  EXPECT_TRUE(with_generated_key_tables(page) == page)
      << "docs/scenes.md differs from the scene reader's key tables; regenerate it from the repository root with "
      << scene_keys_regenerate_command;
}

TEST(SceneKeyReference, TheFuzzDictionaryHoldsEveryKeyAndName) {
  EXPECT_TRUE(scene_fuzz_dictionary() == read_file(source_dir / "fuzz/scene.dict"))
      << "fuzz/scene.dict differs from the scene reader's key tables; regenerate it from the repository root with "
      << scene_keys_regenerate_command;
  const std::string dictionary = scene_fuzz_dictionary();
  for (const char* entry : {R"(key_cfl="\"cfl\":")", R"(key_unlike_attraction="\"unlike_attraction\":")",
                            R"(name_wendland_c2="\"wendland_c2\"")", R"(name_water_height="\"water_height\"")"}) {
    EXPECT_NE(dictionary.find(entry), std::string::npos) << entry;
  }
}

TEST(SceneKeyReference, ATableReplacesWhateverStoodBetweenItsMarkers) {
  const std::string page = read_file(source_dir / "docs/scenes.md");
  const std::string open = "<!-- scene keys: time -->\n";
  const std::size_t at = page.find(open);
  ASSERT_NE(at, std::string::npos);
  std::string stale = page;
  stale.insert(at + open.size(), "| `stale` | number | s | `0` | A key the reader no longer has. |\n");
  EXPECT_EQ(with_generated_key_tables(stale), page);
}

TEST(SceneKeyReference, MarkersMustMatchTheSections) {
  const std::string page = read_file(source_dir / "docs/scenes.md");
  EXPECT_THROW(with_generated_key_tables(page + "<!-- scene keys: nowhere -->\n<!-- end scene keys -->\n"),
               std::invalid_argument);
  EXPECT_THROW(with_generated_key_tables(page + "<!-- scene keys: time -->\n"), std::invalid_argument);
  EXPECT_THROW(with_generated_key_tables("# A page without tables\n"), std::invalid_argument);
}

}  // namespace
}  // namespace tide::io
