# hooke::warnings: the project's warning set, linked privately by every hooke target.
add_library(hooke_warnings INTERFACE)
add_library(hooke::warnings ALIAS hooke_warnings)
target_compile_options(hooke_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                                -Wold-style-cast -Wcast-align -Woverloaded-virtual)
if(HOOKE_WERROR)
  target_compile_options(hooke_warnings INTERFACE -Werror)
endif()
