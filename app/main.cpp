// Entry point of the `ispm` executable: the subcommands live in app/cli/.
#include "cli/cli.h"

int main(int argc, char** argv) {
    return ispm::runCli(argc, argv);
}
