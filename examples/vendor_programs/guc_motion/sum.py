"""The GUC-ECAT manual's motion program "Addition" (GUC-ECAT seed 002, §5.2.3 (1), L2266-2296), C -> Python
(decision GS13): the global ``sum`` keeps the result, the locals ``begin`` and ``end`` (the function's parameters)
bound the addition; the function returns ``sum``. Compiled by GT_Compile, downloaded by GT_Download, run by a
thread (examples/vendor_programs/guc_motion_sum*.py). Same statements, same order; the labels and gotos of the C
become the loop they spell."""

# -----------------------------------------------------------------------------------------------------------------
# Addition
# begin
# end
# -----------------------------------------------------------------------------------------------------------------
sum = 0  # noqa: A001 -- the manual's global "int sum;"


def add(begin, end):
    global sum
    i = begin
    while True:          # lbl_loop:
        cc = i > end
        if cc:
            break        # if(cc) goto lbl_end;
        sum = sum + i
        i = i + 1        # goto lbl_loop;
    return sum           # lbl_end: return sum;
