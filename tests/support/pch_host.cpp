// () => () — the host of the tests' precompiled header (tests/CMakeLists.txt): a translation
// unit compiled with the tests' flags, so that every test executable reuses its header.
int main() { return 0; }
