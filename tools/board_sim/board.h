/* tools/board_sim/board.h: what board_sim.c needs of the board it runs on, given by the board's
 * start-up file (cortex-m.c): a console line and the end of the program. */
#ifndef AMORPH_BOARD_SIM_BOARD_H
#define AMORPH_BOARD_SIM_BOARD_H

/* writes text to the host's console (semihosting SYS_WRITE0 on the Cortex-M boards) */
void board_out(const char* text);
/* highest stack use so far, bytes (the start-up painted the stack) */
unsigned long board_stack_used(void);
/* ends the program: status 0 a success, any other a failure the host sees (QEMU's exit status 1) */
_Noreturn void board_exit(int status);

#endif
