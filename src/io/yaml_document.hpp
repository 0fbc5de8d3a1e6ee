// yaml_document.hpp (private to the io area): a task file's text to one YAML document, with the
// reader's failures said in words and with the line: bytes that are not UTF-8 text, tabs used for
// indentation, nesting deeper than the YAML reader's limit, a second document, text after the end
// of the document (which yaml-cpp ignores silently).
#pragma once

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <string>

namespace rodshape::io_detail {

/// The single YAML document in `text` (reported as `source`); an empty text gives a null node.
/// Throws InputError "<source>:<line>: <what>", e.g. "task.yaml:3: not a text file: invalid byte
/// 0x89 (a task file is YAML, in UTF-8)" or "task.yaml:9: a second YAML document starts here (after
/// '---'); a task file is a single document".
YAML::Node load_single_document(const std::string& text, const std::string& source);

}  // namespace rodshape::io_detail
