# HOOKE_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on every target of the build.
if(HOOKE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
