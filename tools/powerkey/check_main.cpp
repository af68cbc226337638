// `powerkey check` as a program of its own too (the powerkey tool hosts it as `check`):
// powerkey_check --model M [--node N] [--json] FILE... (tools/powerkey/cmd_check.cpp).
int run_check(int argc, char** argv);

int main(int argc, char** argv) { return run_check(argc - 1, argv + 1); }
