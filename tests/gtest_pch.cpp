// Nothing: the object library that builds gtest's precompiled header once for every test
// program (tests/CMakeLists.txt).
