// The translation unit that builds the library tests' precompiled header (CMakeLists.txt:
// god_finger_test_pch); it holds nothing of its own.
