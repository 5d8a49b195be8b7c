// The empty program whose build makes the test executables' precompiled
// header (cmake/precompiled_headers.cmake).
int main() { return 0; }
