// SPDX-License-Identifier: MIT
// Where flange looks for its data files: $FLANGE_DATA_DIR, then <exe>/../share/flange, then the
// source tree unless that is forbidden.
#include "data_dir.h"

#include <gtest/gtest.h>

#include "test_files.h"

namespace flange::runtime {
namespace {

using flange::testing::fresh_test_dir;
using flange::testing::write_file;

// A data folder: only rtl/iir_core.sv marks one.
fs::path make_data_folder(const fs::path& root) {
  fs::create_directories(root / "rtl");
  write_file(root / "rtl" / "iir_core.sv", "");
  return root;
}

TEST(DataDir, TheVariableComesFirst) {
  const fs::path dir = fresh_test_dir("data_dir_variable");
  make_data_folder(dir / "elsewhere");
  make_data_folder(dir / "prefix" / "share" / "flange");
  DataDirSearch search;
  search.data_dir_variable = dir / "elsewhere";
  search.executable = dir / "prefix" / "bin" / "flange";
  search.user_cache = dir / "cache";
  const DataDir found = find_data_dir(search);
  EXPECT_EQ(found.origin, DataOrigin::kEnvironment);
  EXPECT_EQ(found.root, dir / "elsewhere");
  ASSERT_EQ(found.runner_archives.size(), 2u);
  EXPECT_EQ(found.runner_archives[0], dir / "elsewhere" / "lib" / "libflange_tb.a");
  EXPECT_EQ(found.runner_archives[1], dir / "elsewhere" / "lib" / "libflange_model.a");
  EXPECT_EQ(found.runner_cache, dir / "cache" / "flange" / "cosim");
}

TEST(DataDir, AVariableWithoutTheRtlIsAnError) {
  const fs::path dir = fresh_test_dir("data_dir_bad_variable");
  DataDirSearch search;
  search.data_dir_variable = dir;
  EXPECT_THROW(find_data_dir(search), DataDirNotFound);
}

TEST(DataDir, AnInstalledFlangeFindsShareBesideBin) {
  const fs::path dir = fresh_test_dir("data_dir_installed");
  make_data_folder(dir / "prefix" / "share" / "flange");
  DataDirSearch search;
  search.executable = dir / "prefix" / "bin" / "flange";
  search.no_source_tree = true;
  const DataDir found = find_data_dir(search);
  EXPECT_EQ(found.origin, DataOrigin::kInstalled);
  EXPECT_EQ(found.root, dir / "prefix" / "share" / "flange");
}

TEST(DataDir, ABuildFolderFallsBackToTheSourceTree) {
  const fs::path dir = fresh_test_dir("data_dir_build_folder");
  DataDirSearch search;
  search.executable = dir / "flange";
  const DataDir found = find_data_dir(search);
  EXPECT_EQ(found.origin, DataOrigin::kSourceTree);
  EXPECT_EQ(found.root, fs::path(FLANGE_SOURCE_DIR));
  EXPECT_EQ(found.runner_cache, fs::path(FLANGE_BINARY_DIR) / "cosim_cache");
  ASSERT_EQ(found.runner_archives.size(), 2u);
  EXPECT_EQ(found.runner_archives[0].filename(), "libflange_tb.a");
}

TEST(DataDir, TheSourceTreeCanBeForbidden) {
  const fs::path dir = fresh_test_dir("data_dir_no_source_tree");
  DataDirSearch search;
  search.executable = dir / "flange";
  search.no_source_tree = true;
  try {
    find_data_dir(search);
    FAIL() << "the source tree was used although it is forbidden";
  } catch (const DataDirNotFound& missing) {
    EXPECT_NE(std::string(missing.what()).find("FLANGE_DATA_DIR"), std::string::npos)
        << missing.what();
  }
}

}  // namespace
}  // namespace flange::runtime
