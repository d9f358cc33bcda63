// Where the tests find the source tree (scenes, docs, fuzz inputs) and the vct binary. The build
// generates their definitions (tests/CMakeLists.txt) into one small object instead of putting the
// paths on every test file's command line: ccache rewrites paths only where they name files, so a
// define holding the checkout's path made every test object of a clone elsewhere (CI's) a miss.
// Force-included into every test file.
#pragma once

extern const char* const vct_test_source_dir;
extern const char* const vct_test_binary;

#define VCT_SOURCE_DIR vct_test_source_dir
#define VCT_BINARY vct_test_binary
