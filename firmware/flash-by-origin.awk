# Flash bytes of a linked image by where they come from, read from its GNU ld map file:
# every input section placed in an output section that lives in flash (code, constants,
# vectors, the initial values of .data), summed by the archive it came from.
#   engine   libfeel_engine_m4.a: the engine's code and constants; since the engine is
#            optimised at link time, the link's ltrans partitions (only the engine's
#            objects are LTO objects: firmware/CMakeLists.txt)
#   libgcc   soft-float double routines and 64-bit division the engine's code calls
#   libm     the math library (expf, sqrt, ...; the board's own double sin, cos, exp and
#            expm1, board_math.c, in place of newlib's)
#   runtime  newlib, libstdc++ and the semihosting syscalls: printf, malloc, exit
#   program  the test or size program, start-up and the heap guard
# Each byte is counted once, for the first input section that covers it: the linker merges
# equal strings (and equal constant sections) across files, and the map then lists every
# file's copy at the same address with its full size. (Counted once per file, the parts
# exceeded the image by 150 to 500 bytes, the engine's partitions most, and a change that
# moved a string between partitions could show the engine larger when the image shrank.)
# The parts now add up to the image's text + data.
function hex(h,  i, n) {
    n = 0; h = tolower(h); sub(/^0x/, "", h)
    for (i = 1; i <= length(h); ++i) n = n * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
    return n
}
/^Linker script and memory map/ { on = 1; next }
!on { next }
/^\.[A-Za-z_]/ {
    split($0, f, /[ \t]+/)
    flash = f[1] ~ /^\.(isr_vector|text|ARM\.extab|ARM\.exidx|preinit_array|init_array|fini_array|data)$/
    top = 0  # the end of the bytes counted so far in this output section
}
flash {
    n = split($0, f, /[ \t]+/)
    # An input section: [name] 0xADDRESS 0xSIZE FILE (the name may be on the line before).
    if (n >= 4 && f[n - 2] ~ /^0x/ && f[n - 1] ~ /^0x/ && f[n] !~ /^0x/) {
        file = f[n]
        if (file ~ /libfeel_engine_m4\.a|\.ltrans[0-9]*\.ltrans\.o$/) k = "engine"
        else if (file ~ /libgcc\.a/) k = "libgcc"
        else if (file ~ /libm\.a|board_(math|libm)\.c\.obj$/) k = "libm"
        else if (file ~ /\/lib[^\/]*\.a\(|crt[^\/]*\.o$/) k = "runtime"
        else k = "program"
        start = hex(f[n - 2]); end = start + hex(f[n - 1])
        if (start < top) start = top
        if (end > start) { bytes[k] += end - start; top = end }
    }
}
END { printf "%d %d %d %d %d\n", bytes["engine"], bytes["libgcc"], bytes["libm"], bytes["runtime"], bytes["program"] }
