# Writes OUT (a C++ header defining DYNVO_BUILD_COMMIT) with the git commit of SOURCE_DIR,
# "-dirty" appended when the tree has changes, "unknown" outside a git checkout. Run at every
# build (src/core/CMakeLists.txt); the file is rewritten only when the commit changes, so an
# unchanged tree rebuilds nothing.
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed ERROR_QUIET)
if(failed OR commit STREQUAL "")
  set(commit "unknown")
endif()
set(text "#pragma once\n#define DYNVO_BUILD_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
