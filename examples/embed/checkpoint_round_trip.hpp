#pragma once

/// Runs a small dam break straight and through a checkpoint file; true when both end bitwise equal.
bool checkpoint_round_trip();
