#pragma once
// Runs scripts/plot_figures.py (matplotlib, Debian's python3-matplotlib) on figure specs the library wrote.
#include <filesystem>
#include <vector>

namespace hooke::cli {

/// Draws each spec (JSON) into a PNG beside it with `$HOOKE_PYTHON` (default /usr/bin/python3) running
/// `$HOOKE_PLOT_SCRIPT` (default the repository's scripts/plot_figures.py), MPLBACKEND=Agg.
/// @throws IoError when the interpreter cannot be started or the script fails (its stderr says why)
void plot_figures(const std::vector<std::filesystem::path>& specs);

}  // namespace hooke::cli
