# Writes the version header at every build (cmake -P, called by the hvsph_version
# target): configure_file rewrites it only when the text changes, so an unchanged
# version rebuilds nothing, and a new commit or an edit (-dirty) is never missed by a
# build directory configured earlier.
# In: SRC_DIR (the source tree), IN (version.h.in), OUT (the generated header),
#     RELEASE (project()'s VERSION, e.g. 0.9.0), COMMIT_OPTION (the HVSPH_COMMIT cache
#     option, may be empty).
# The version is "<RELEASE> (commit <commit>)". The commit, first found:
#  1. -DHVSPH_COMMIT=... given to cmake (a packager's own name for the build);
#  2. the abbreviated hash of the checkout's HEAD, with "-dirty" when tracked files
#     differ from it (`git describe --always --dirty` with every tag excluded, so
#     that a tag never replaces the hash). safe.directory: a checkout owned by another
#     user (a mounted volume, a clone made as another user, built as root) is read
#     too; git refuses it otherwise;
#  3. cmake/archive-version.txt as `git archive` writes it (.gitattributes marks it
#     export-subst, so a tarball made by `git archive` carries its commit's hash);
#  4. "unknown" (a copy of the tree without its history).
# HVSPH_VERSION_SOURCE names which one it was (option, git, archive, none).
set(HVSPH_VERSION_SOURCE none)
set(HVSPH_COMMIT "")
if(COMMIT_OPTION)
  set(HVSPH_COMMIT "${COMMIT_OPTION}")
  set(HVSPH_VERSION_SOURCE option)
else()
  execute_process(COMMAND git -c safe.directory=* describe --always --dirty --exclude=*
                  WORKING_DIRECTORY ${SRC_DIR}
                  OUTPUT_VARIABLE HVSPH_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
  if(HVSPH_COMMIT)
    set(HVSPH_VERSION_SOURCE git)
  elseif(EXISTS ${SRC_DIR}/cmake/archive-version.txt)
    file(STRINGS ${SRC_DIR}/cmake/archive-version.txt HVSPH_ARCHIVE_VERSION LIMIT_COUNT 1)
    # unsubstituted (a checkout's own copy) it still reads "$Format:...$"
    if(HVSPH_ARCHIVE_VERSION MATCHES "^[0-9a-f]+$")
      set(HVSPH_COMMIT "${HVSPH_ARCHIVE_VERSION}")
      set(HVSPH_VERSION_SOURCE archive)
    endif()
  endif()
endif()
if(NOT HVSPH_COMMIT)
  set(HVSPH_COMMIT "unknown")
endif()
if(NOT RELEASE MATCHES "^[0-9]+\\.[0-9]+\\.[0-9]+$")
  message(FATAL_ERROR "version.cmake: RELEASE '${RELEASE}' is not MAJOR.MINOR.PATCH")
endif()
# the commit goes into C string literals and file headers: one printable word
string(REGEX REPLACE "[^A-Za-z0-9._+~:-]" "_" HVSPH_COMMIT "${HVSPH_COMMIT}")
configure_file(${IN} ${OUT} @ONLY)
