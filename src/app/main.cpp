#include "app/cli.hpp"

int main(int argc, char** argv) { return atrium::run_cli(argc, argv); }
