// Linked into every executable of the sanitizer build (RIEMANN_SANITIZE,
// cmake/RiemannSanitize.cmake), and only there.
//
// dlclose does nothing: libraries loaded at run time stay mapped until the
// process ends. Mesa's GL driver (swrast_dri.so, with LLVM) is dlopen'ed by
// libGLX_mesa and dlclose'd when VTK closes the X display; the few blocks it
// keeps in its globals then look leaked to LeakSanitizer, which runs at exit,
// and their stacks point into an unmapped "<unknown module>" that no
// suppression can name. Kept mapped, the driver's globals still reach them
// and its frames keep their library's name. This changes nothing in the
// project's code, whose leaks are still reported.
extern "C" __attribute__((visibility("default"))) int dlclose(void*)
{
  return 0;
}
