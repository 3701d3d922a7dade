/*
 * The TPU channel the kernel's board support (k_board_robocube.c) reads TCR1
 * through for the kernel's fine time stamp (k_timestamp), once it is started
 * (k_timestamp_start; the TPU driver refuses the channel from then on:
 * board_tpu_reserved). TCR1's rate at TPUMCR 0x4ACD and fsys = 16.777216 MHz.
 */
#ifndef ROBOCUBE_TPU_STAMP_H
#define ROBOCUBE_TPU_STAMP_H

#define ROBOCUBE_TPU_STAMP_CHANNEL 15u
#define ROBOCUBE_TCR1_HZ 1048576u

#endif /* ROBOCUBE_TPU_STAMP_H */
