// The device's test programs have no name service, and say so to the linker.
//
// cmake/toolchain-armel.cmake links every program statically and runs it under qemu-arm without
// the target's shared libraries. GoogleTest can stream results to a socket
// (--gtest_stream_result_to=HOST:PORT) and looks the host up with getaddrinfo, which in a static
// glibc program needs glibc's shared NSS modules at run time: so the linker warned about it on
// every test program, and the lookup could not work on the device anyway. Linked with
// --wrap=getaddrinfo,--wrap=freeaddrinfo (cmake/OctopointDeviceGTest.cmake), GoogleTest's calls
// come here instead and glibc's resolver is not linked at all: a lookup fails with EAI_FAIL, which
// GoogleTest reports as a warning before it runs the tests as usual. Nothing else in octopoint
// resolves names.
#include <netdb.h>

extern "C" int __wrap_getaddrinfo(const char* /*node*/, const char* /*service*/,
                                  const addrinfo* /*hints*/, addrinfo** result) {
  *result = nullptr;
  return EAI_FAIL;
}

extern "C" void __wrap_freeaddrinfo(addrinfo* /*list*/) {}  // getaddrinfo never returns a list
