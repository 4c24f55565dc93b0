/* mcspec version (also mcspec --version): the release of the library the
 * command is built with. */
#include "cli.h"

#include "mcspec.h"

#include <stdio.h>

#define CMD "mcspec version"

static const char help[] =
    "usage: mcspec version\n"
    "       mcspec --version\n"
    "\n"
    "Prints one line, \"mcspec VERSION\": the release of the mcspec library the\n"
    "command is linked with (mcs_version(), include/mcspec/version.h; semantic\n"
    "versioning, CHANGELOG.md).\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage (one line on stderr).\n";

int cli_cmd_version(int argc, char **argv)
{
    cli_parser p = {CMD, help, NULL, 0u, NULL, 0u, 0u, NULL};
    int rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED)
        return rc == CLI_HELP ? CLI_EXIT_OK : rc;
    printf("mcspec %s\n", mcs_version());
    return CLI_EXIT_OK;
}
