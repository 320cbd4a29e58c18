# CLI11 (Debian libcli11-dev): command-line parsing for the hooke tool.
find_package(CLI11 CONFIG REQUIRED)
