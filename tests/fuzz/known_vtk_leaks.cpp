// VTK 9.1's XML reader leaks a little memory on some malformed files (inside VTK,
// before import_vtu sees the result; refusing such files earlier would mean
// parsing the XML ourselves). LeakSanitizer is told to ignore exactly these two
// allocation sites in the programs that feed malformed .vtu files to the importer
// (fuzz_vtu and test_fuzz_replay); every other leak is still reported.
// `scripts/study fuzz` runs fuzz_vtu without leak detection and with fast unwinding
// (a full stack for every allocation would slow the fuzzer down many times over;
// docs/verification/fuzzing.md); the replay test checks the corpus.
//
//   vtkXMLReader::ReadArrayValues            an array iterator when reading fails
//   vtkXMLUnstructuredGridReader::ReadPieceData  the cell-types array when the
//                                            cells cannot be read
//
// Matching by function needs the full stack of each allocation: VTK's libraries
// are built without frame pointers, so the fast unwinder stops inside them.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:vtkXMLReader::ReadArrayValues\n"
         "leak:vtkXMLUnstructuredGridReader::ReadPieceData\n";
}

extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }
