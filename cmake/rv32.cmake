# Helpers for RV32 ELFs that run on the QEMU `virt` devboard.

# qr_rv32_executable(NAME SOURCES...): NAME.elf linked with the devboard runtime and libgcc, with
# a link map and a size report beside it.
function(qr_rv32_executable name)
  add_executable(${name} ${ARGN})
  set_target_properties(${name} PROPERTIES SUFFIX ".elf")
  target_link_libraries(${name} PRIVATE rv32virt_runtime "${QR_RV32_LIBGCC}")
  target_link_options(${name} PRIVATE "-Wl,-Map=$<TARGET_FILE:${name}>.map")
  add_custom_command(TARGET ${name} POST_BUILD
    COMMAND ${CMAKE_SIZE} $<TARGET_FILE:${name}> > $<TARGET_FILE:${name}>.size
    VERBATIM)
endfunction()
