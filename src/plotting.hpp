// src/plotting.hpp - pictures drawn by gnuplot, with no user text in its language.
//
// gnuplot is a language with a shell escape (`system`, backquotes). cdref hands it a script it
// writes itself: every string in it (titles, labels, the names of queries and families) goes
// through gp_string, a single-quoted literal in which nothing is interpreted; data are inline
// datablocks of numbers; the picture comes back on gnuplot's standard output (the script never
// names a file), and cdref writes it through its checked output layer. gnuplot runs with no
// shell: its script is a temporary file cdref names.
#pragma once

#include <string>

namespace cdref::cli {

// A gnuplot single-quoted string literal of `text`: quotes doubled (the only special character
// inside such a literal), control characters (a newline would end the command) replaced by
// blanks.
std::string gp_string(const std::string& text);

// Runs gnuplot on `script` (which sets an svg terminal and no output file) and returns what it
// drew. Throws std::runtime_error when gnuplot cannot be run or fails (with its messages).
std::string gnuplot_svg(const std::string& script);

}  // namespace cdref::cli
