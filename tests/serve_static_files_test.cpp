// The page's files (tide/serve/static_files.hpp): a request finds a file of the static folder
// and nothing outside it, however the path is written.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tide/serve/static_files.hpp"

namespace tide::serve {
namespace {

class StaticFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = std::filesystem::temp_directory_path() /
            ("tide_static_files_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(base_);
    std::filesystem::create_directories(root() / "lib");
    write(root() / "index.html");
    write(root() / "app.js");
    write(root() / "lib" / "view.js");
    write(root() / "notes.txt");
    write(base_ / "secret.js");  // beside the folder, not in it
    std::filesystem::create_symlink(base_ / "secret.js", root() / "link.js");
    std::filesystem::create_directory_symlink(base_, root() / "up");
  }
  void TearDown() override { std::filesystem::remove_all(base_); }

  std::filesystem::path root() const { return base_ / "web"; }
  static void write(const std::filesystem::path& file) { std::ofstream(file) << "x"; }

  std::filesystem::path base_;
};

TEST_F(StaticFiles, FindsThePagesFiles) {
  const auto index = find_static_file(root(), "/");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->path.filename(), "index.html");
  EXPECT_EQ(index->content_type, "text/html; charset=utf-8");
  const auto script = find_static_file(root(), "/lib/view.js");
  ASSERT_TRUE(script);
  EXPECT_EQ(script->content_type, "text/javascript; charset=utf-8");
}

TEST_F(StaticFiles, RefusesEveryWayOut) {
  for (const char* path : {"/../secret.js", "/lib/../../secret.js", "/./app.js", "/lib/..", "..", "app.js", "",
                           "/..\\secret.js", "/lib\\..\\..\\secret.js", "/app.js\n", "/app%2ejs", "/link.js",
                           "/up/secret.js", "//etc/passwd", "/lib", "/missing.js", "/notes.txt"}) {
    EXPECT_FALSE(find_static_file(root(), path)) << path;
  }
  EXPECT_FALSE(find_static_file(root(), std::string("/app.js\0.html", 13))) << "an embedded NUL";
}

TEST_F(StaticFiles, AFolderThatIsNotThereServesNothing) { EXPECT_FALSE(find_static_file(base_ / "nowhere", "/")); }

}  // namespace
}  // namespace tide::serve
