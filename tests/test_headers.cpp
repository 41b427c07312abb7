// The target that owns the test programs' precompiled headers (tests/CMakeLists.txt) needs one
// source of its own.
