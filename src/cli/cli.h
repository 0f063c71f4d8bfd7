/*
 * cli.h -- what the user's commands share beyond tool.h: reading a
 * file's points (weighted or not) and building its triangulation,
 * CGAL's canonical form of a file, writing a canonical form; and the
 * commands the table in cli.c runs from the other files of src/cli/
 * (the bench commands: src/bench/bench.h).
 */
#ifndef DD_CLI_H
#define DD_CLI_H

#include "tool/tool.h"

/* The points of FILE (.xyz or .off, dd_read_points); 0, or EXIT_INPUT
 * after a message naming the problem.                                   */
int load_file(const char *cmd, const char *path, double **xyz, uint32_t *np);
/* Reads FILE and builds its DT in *t; 0, or the exit status after a
 * message on stderr naming the file and the problem.                    */
int build_file(const char *cmd, const char *path, dd_tri **t);
/* The points and weights of FILE (dd_read_weighted: *w NULL for a file
 * without weights); 0, or EXIT_INPUT after a message.                   */
int load_weighted_file(const char *cmd, const char *path, double **xyz, double **w, uint32_t *np);
/* Reads FILE and builds its regular triangulation (its DT when it has no
 * weights) with dd_create_ex and flags; 0, or the exit status after a
 * message naming the file and the problem.                              */
int build_weighted_file(const char *cmd, const char *path, unsigned flags, dd_tri **t);
/* `cgal-tets FILE`: CGAL's canonical form on stdout (regular for weights,
 * discard selecting Discard_hidden_points); 0 or EXIT_INPUT.            */
int cgal_tets_file(const char *path, int discard);
/* A canonical form on stdout, one line "a b c d" a cell. */
void write_tets(const int32_t *tets, size_t n);

/* The user's commands living in other files: argc and argv from the
 * command's name on; an exit status, or EXIT_SHOW_USAGE.                */
int cmd_delete(int argc, char **argv);
int cmd_time(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_locate(int argc, char **argv);
int cmd_move(int argc, char **argv);
int cmd_hidden(int argc, char **argv);
int cmd_cgal_hidden(int argc, char **argv);

#endif
