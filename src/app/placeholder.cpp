// Replaced by the frame loop.
