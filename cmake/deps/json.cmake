# nlohmann-json (Debian nlohmann-json3-dev): JSON reports.
find_package(nlohmann_json 3 CONFIG REQUIRED)
