# Warnings on for our own targets only (system headers stay quiet through SYSTEM includes).
add_library(vct_warnings INTERFACE)
target_compile_options(vct_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Wunused
  -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion -Wformat=2
  -Wimplicit-fallthrough)

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
