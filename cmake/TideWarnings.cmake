# Compiler flags shared by every TideSPH target.
add_library(tide_warnings INTERFACE)
target_compile_options(tide_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic>
  $<$<AND:$<BOOL:${TIDE_WERROR}>,$<CXX_COMPILER_ID:GNU,Clang>>:-Werror>)
if(TIDE_SANITIZE)
  target_compile_options(tide_warnings INTERFACE
    -fsanitize=${TIDE_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  target_link_options(tide_warnings INTERFACE -fsanitize=${TIDE_SANITIZE})
endif()
