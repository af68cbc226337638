// Footprint firmware (b_strict): firmware (b), the bus monitor of every model, reading only
// frames in the manuals' form (powerkey::reading::strict): what the tolerant reading costs.
#define FW_B_READING strict
#include "fw_b.cpp"
