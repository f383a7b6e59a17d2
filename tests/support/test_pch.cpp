// The translation unit that compiles the test programs' precompiled header
// (tests/CMakeLists.txt, atrium_test_pch); it has no code of its own.
