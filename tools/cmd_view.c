#include "cmd.h"
int cmd_view(int argc, char** argv) { (void)argc; (void)argv; return 2; }
int tool_write_viewer(const am_lattice* lat, const am_env* env, const am_eval_def* eval, const char* title, const char* path) { (void)lat; (void)env; (void)eval; (void)title; (void)path; return 1; }
