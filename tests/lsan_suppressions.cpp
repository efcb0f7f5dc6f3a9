// Linked into every test program and the baize program in the BAIZE_SANITIZE build: leaks that
// LeakSanitizer reports in system libraries, not in Baize. Fontconfig (used by Cairo for the charts'
// font) keeps its configuration cache for the life of the process and never frees it; OSMesa keeps
// the state it allocates when a context is made current (OSMesaMakeCurrent) after the context is
// destroyed, which render/osmesa_context.cpp does.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libfontconfig.so\n"
         "leak:libOSMesa.so\n";
}
