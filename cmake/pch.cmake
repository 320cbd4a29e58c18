# hooke_precompile_headers(target): precompiles the heavy third-party headers every translation unit parses
# (Eigen's dense and sparse modules and the standard containers) once per target. Parsing them took about 2.5 s of
# a typical 12-20 s translation unit here; each target builds its own header with its own flags (release, -Werror,
# sanitizers), so nothing is shared between configurations. HOOKE_PRECOMPILE_HEADERS=OFF turns it off.
option(HOOKE_PRECOMPILE_HEADERS "Precompile Eigen and the standard headers per target" ON)
function(hooke_precompile_headers target)
  if(HOOKE_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE <Eigen/Dense> <Eigen/Sparse> <vector> <string> <memory>
                                                <functional> <algorithm>)
  endif()
endfunction()
