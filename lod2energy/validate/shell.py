"""Shell-level checks (301-307). STUB: to be implemented."""


def check_shell(vertices, shell, tol, volumetric):
    return []
