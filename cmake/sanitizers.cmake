# HOOKE_SANITIZE: ON (or address) = AddressSanitizer + UndefinedBehaviorSanitizer on every target of the build, with
# float-cast-overflow (out-of-range double -> integer casts), which gcc leaves out of -fsanitize=undefined, and
# without UBSan's null and alignment checks: they instrument every reference binding and member access of Eigen's
# expression templates and doubled the compile time of the UBSan checks (measured on fem/elastic_block.cpp at -O1:
# ASan alone 33 s, with all of UBSan 66 s, without these two 36 s), and what they guard is covered otherwise: a null
# dereference faults under ASan, and x86-64 does not trap on an unaligned load (C++17's aligned new keeps Eigen's
# fixed-size members aligned);
# thread = ThreadSanitizer (the tsan preset: the interactive layer's tests, run with one OpenMP thread, since
# libgomp is not instrumented).
if(HOOKE_SANITIZE STREQUAL "thread")
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
elseif(HOOKE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined,float-cast-overflow -fno-sanitize=null,alignment
                      -fno-omit-frame-pointer -fno-sanitize-recover=undefined,float-cast-overflow)
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
endif()
