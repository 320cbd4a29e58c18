#pragma once
// The CLI's Python side: the figures (scripts/plot_figures.py, matplotlib) and the Dask studies (hooke.batch), each run
// as a child process of Debian's /usr/bin/python3 with hooke's Python package on its path.
#include <filesystem>
#include <string>
#include <vector>

namespace hooke::cli {

/// Runs `$HOOKE_PYTHON` (default /usr/bin/python3) with `args`, its standard streams this process's, hooke's Python
/// package on PYTHONPATH (the build tree's when this hooke runs from its build tree, else the installed one) and
/// MPLBACKEND=Agg; returns the child's exit code.
/// @throws IoError when the interpreter cannot be started or ends on a signal (naming it)
int run_python(const std::vector<std::string>& args);

/// Draws each spec (JSON) into a PNG beside it with `$HOOKE_PLOT_SCRIPT` (default the repository's
/// scripts/plot_figures.py) under run_python.
/// @throws IoError when the interpreter cannot be started or the script fails (its stderr says why)
void plot_figures(const std::vector<std::filesystem::path>& specs);

}  // namespace hooke::cli
