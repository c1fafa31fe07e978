// Compiled into every executable of the sanitizer build (scripts/build.sh --sanitize) so that a
// binary from build-sanitize/ runs with the right options wherever it is started, including
// ctest's test discovery at build time. The environment (ASAN_OPTIONS, LSAN_OPTIONS, ...) still
// overrides these.
extern "C" {

// fast_unwind_on_malloc=0: Open MPI and LIGGGHTS are built without frame pointers, so the fast
// unwinder stops at their first frame (often in an unloaded MPI plugin, "<unknown module>") and
// the allocation stack names no library the suppressions below could match.
const char* __asan_default_options() {
  return "detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:"
         "strict_init_order=1:fast_unwind_on_malloc=0";
}

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

// Only leaks whose allocation stack lies in third-party libraries, each with its reason. A leak
// of ours that passes through one of them (a LIGGGHTS fix of ours, say) would be hidden too: keep
// this list short.
const char* __lsan_default_suppressions() {
  return
      // Open MPI keeps component, datatype and communicator tables until the process ends
      // (MPI_Finalize frees only part of them); reported at the exit of every MPI program.
      "leak:libmpi.so\n"
      "leak:libopen-pal.so\n"
      "leak:libopen-rte.so\n"
      // hwloc, Open MPI's topology library, caches the topology for the process lifetime.
      "leak:libhwloc.so\n"
      // Open MPI's progress thread (libevent's event loop) in a process started by mpirun -np 2
      // leaves 32 bytes from one of its plugins, which is unloaded before LeakSanitizer looks, so
      // only libevent's frame has a name (dem_mpi_loads_follow_migrating_atoms,
      // dem_equivalence_20000_steps_np2). Nothing of ours runs in that thread.
      "leak:event_base_loop\n"
      // LIGGGHTS 3.8: Error::all ends the process with exit(1) from inside a command, with the
      // whole instance still allocated; some of its classes never free what their constructors
      // allocate (Error's SpecialMessages, the style maps).
      "leak:libliggghts.so\n"
      // PETSc 3.18: when an option inside a PetscOptionsBegin/End block is refused
      // (-ksp_type nonsense), the error return skips PetscOptionsEnd and the block's title string
      // (32 bytes) is never freed. Only that frame: PETSc objects of ours are not hidden.
      "leak:PetscOptionsBegin_Private\n";
}

}  // extern "C"
