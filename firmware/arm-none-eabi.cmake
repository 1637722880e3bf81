# Cross-compiling for a Cortex-M4F with Debian's arm-none-eabi-gcc (gcc-arm-none-eabi,
# libnewlib-arm-none-eabi, libstdc++-arm-none-eabi-newlib). Used by `make firmware`.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
# The engine's archive holds link-time-optimisation objects (CMakeLists.txt): the gcc-ar
# wrappers index their symbols through the LTO plugin.
set(CMAKE_AR arm-none-eabi-gcc-ar)
set(CMAKE_RANLIB arm-none-eabi-gcc-ranlib)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
# -ffp-contract=off: no fused multiply-adds, so every float operation rounds as on x86 and
# the forces can match the x86 build's bit for bit.
set(FEEL_M4_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -ffp-contract=off -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${FEEL_M4_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${FEEL_M4_FLAGS} -fno-exceptions -fno-rtti -fno-threadsafe-statics")
set(CMAKE_C_FLAGS_RELEASE_INIT "-Os")
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-Os")
