"""The Maxima stage: one Maxima session and the text sent to it, the names Maxima
already defines, what a .mxm may do (lock-down), the OS limits and sandbox, the
child processes, and the files a program loads (Make/Ninja dependency files)."""
