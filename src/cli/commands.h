/* Entry points of the subcommands, one file each. */
#ifndef FL_CLI_COMMANDS_H
#define FL_CLI_COMMANDS_H

int cmd_version(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_demo(int argc, char **argv);
int cmd_delaunay(int argc, char **argv);
int cmd_graph(int argc, char **argv);
int cmd_reconstruct(int argc, char **argv);

#endif
