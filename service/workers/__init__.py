"""Child processes that do the CPU-heavy work (generation, rendering) away from the event loop,
and the pool that feeds, times out, replaces and retries them."""
