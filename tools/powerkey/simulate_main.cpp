// The `powerkey simulate` command on its own too (tools/powerkey/cmd_simulate.cpp; the powerkey
// tool hosts it as `simulate`): powerkey_simulate --model M [--node N] [--press T:K] [FILE...]
int run_simulate(int argc, char** argv);

int main(int argc, char** argv) { return run_simulate(argc - 1, argv + 1); }
