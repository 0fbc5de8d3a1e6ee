// output_files.hpp: what a run may do to the files in the way of its outputs (issue 24). An
// output that is one of the run's own inputs (its task file, its URDF) is bad input. A file where
// an output goes is replaced or removed only when it is recognisably rodshape's, an earlier run's
// output: by the signature its JSON begins with, the header its CSV begins with, or the comment
// its SVG begins with. Any other file in the way is bad input, named, and left alone. A device, a
// FIFO or a symbolic link at an output is refused (issue 43), and a run's files are written as a
// set: all checked, all written to temporaries, then renamed (write_output_set()).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rodshape/figures/figures.hpp"

namespace rodshape {

/// The first member of every JSON document rodshape writes into an output directory (plan.json,
/// joint_trajectory.json, base_joint_trajectory.json, validation.json): {"generator": "rodshape
/// <version>", ...}.
inline constexpr const char* kGeneratorKey = "generator";
std::string generator_signature();  // "rodshape <version>"
// svg_signature_comment(): the comment every SVG and HTML page rodshape writes begins with
// (rodshape/figures/figures.hpp).

/// True when the file at `path` is one rodshape writes under its name: a JSON document whose
/// first member is kGeneratorKey with a value starting "rodshape", an SVG or an HTML page with
/// the signature comment, trajectory.csv (with or without a moving base's columns) or
/// validation.csv with their exact headers, joint_trajectory.csv and base_joint_trajectory.csv
/// with a header "t,<joint names>". False for anything else, including files it cannot read and
/// symbolic links (not followed).
bool is_rodshape_output(const std::string& path);

/// InputError "<output>: is <input>, an input of this run; ..." when `output` names the same file
/// as one of `inputs` (through links, or as a hard link).
void check_not_an_input(const std::string& output, const std::vector<std::string>& inputs);

/// For each of `names` in `directory`: InputError when it is one of `inputs`, a device, a FIFO or a
/// symbolic link (check_output_path()), or an existing file that is not rodshape's
/// (is_rodshape_output), naming it. Writes and removes nothing, opens no device or FIFO.
void check_output_files(const std::string& directory,
                        const std::vector<std::string>& names,
                        const std::vector<std::string>& inputs);

/// Removes those of `names` in `directory` that are rodshape's outputs (an earlier run's); other
/// files are left alone. InputError when one cannot be removed.
void remove_earlier_outputs(const std::string& directory, const std::vector<std::string>& names);

/// The files of one run, to be written together by write_output_set().
struct OutputSet {
  std::vector<std::pair<std::string, std::string>> files;  // (name in the directory, content)
  std::vector<std::string> stale;  // names not written: an earlier run's files there are removed
  void append(OutputSet other);
};

/// Refuses a `directory` that is a symbolic link or not a directory (check_output_directory(),
/// plan_output.hpp), creates it (and its parents) if missing, writes set.files into it as one set
/// (write_files_atomically(): every path checked before any is written, all written to
/// temporaries, then renamed; a refused path or a failed write changes nothing), then removes the
/// earlier run's files among set.stale (remove_earlier_outputs()). Returns the names written, in
/// order. InputError naming the directory or the path.
std::vector<std::string> write_output_set(const std::string& directory, OutputSet set);

}  // namespace rodshape
