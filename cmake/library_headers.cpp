// The target that owns the libraries' shared precompiled header (CMakeLists.txt,
// vorodg_shared_headers) needs one source of its own.
