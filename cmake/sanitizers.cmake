# HOOKE_SANITIZE: ON (or address) = AddressSanitizer + UndefinedBehaviorSanitizer on every target of the build, with
# float-cast-overflow (out-of-range double -> integer casts), which gcc leaves out of -fsanitize=undefined;
# thread = ThreadSanitizer (the tsan preset: the interactive layer's tests, run with one OpenMP thread, since
# libgomp is not instrumented).
if(HOOKE_SANITIZE STREQUAL "thread")
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
elseif(HOOKE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined,float-cast-overflow)
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
endif()
