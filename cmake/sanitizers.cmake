# HOOKE_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on every target of the build, with float-cast-overflow
# (out-of-range double -> integer casts), which gcc leaves out of -fsanitize=undefined.
if(HOOKE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined,float-cast-overflow)
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
endif()
