#include "cmd.h"
int cmd_plot(int argc, char** argv) { (void)argc; (void)argv; return 2; }
int tool_write_plot(int ndirs, char** dirs, const char* path) { (void)ndirs; (void)dirs; (void)path; return 1; }
