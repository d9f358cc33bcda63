# Warnings on for our own targets only (system headers stay quiet through SYSTEM includes).
add_library(vct_warnings INTERFACE)
target_compile_options(vct_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Wunused
  -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion -Wformat=2
  -Wimplicit-fallthrough)

# Sanitizer builds compile at -O1 (it comes after CMAKE_CXX_FLAGS_RELEASE's -O3 on the command line,
# and the last -O wins): half the compile time of -O3 under ASan+UBSan (stage_compare.cpp 31.7 →
# 16.6 s, a test file 19.1 → 10.0 s of CPU), which is most of a cold CI (docs/performance.md, "CI"),
# and the level the sanitizers' own documentation suggests. No -march and no fast-math at either
# level, so the floating-point results the tests assert are the same bits.
if(VCT_SANITIZE OR VCT_TSAN)
  add_compile_options(-O1)
endif()
if(VCT_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
if(VCT_TSAN)
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  # parallel_for runs on std::thread here: TSan cannot see libgomp's barriers (ref/core/parallel.cpp).
  add_compile_definitions(VCT_TSAN_THREADS=1)
  add_link_options(-fsanitize=thread)
endif()
