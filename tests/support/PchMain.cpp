// The executable that owns a precompiled header the suites reuse (tests/CMakeLists.txt): built
// with the suites' settings, so that its header is valid for every one of them. Never run.
int main() {
    return 0;
}
