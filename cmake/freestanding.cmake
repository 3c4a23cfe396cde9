# Flags for the freestanding layers (fixedpoint, common, qr/core, the RV32 boards). They apply on
# the host build too, so a rule broken there breaks the host build first. Link it PRIVATE: the
# flags are for building a freestanding library, not for the host programs that use it.
add_library(qr_freestanding INTERFACE)
target_compile_options(qr_freestanding INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-fno-exceptions -fno-rtti -fno-threadsafe-statics>
)
