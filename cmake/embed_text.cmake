# Writes OUTPUT, a C++ source defining `const char* const NAME` (namespace NAMESPACE) as the text of
# INPUT, in a raw string literal. Run with cmake -P at build time, so an edit of INPUT rebuilds it.
file(READ "${INPUT}" text)
string(FIND "${text}" ")embedded\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw string's closing delimiter")
endif()
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by cmake/embed_text.cmake; do not edit.\n"
  "namespace ${NAMESPACE} {\n"
  "extern const char* const ${NAME};\n"
  "const char* const ${NAME} = R\"embedded(${text})embedded\";\n"
  "}\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
