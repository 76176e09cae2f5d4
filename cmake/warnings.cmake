# One interface target carries the project's warning flags; every ispm target links it.
add_library(ispm_warnings INTERFACE)
target_compile_options(ispm_warnings INTERFACE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
      -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wnull-dereference
      -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough
      # Designated initialisers leave the rest at their defaults on purpose.
      -Wno-missing-field-initializers
      # GCC 12 reports false overlaps in std::string concatenation at -O2 (GCC bug 105651).
      -Wno-restrict>)
if(ISPM_WERROR)
    target_compile_options(ispm_warnings INTERFACE $<$<COMPILE_LANGUAGE:CXX>:-Werror>)
endif()
