"""The memo's method (Tech Memo 104), stage by stage: a numerical package (numpy and scipy only).

Modules, in the memo's order (reading guide section 1):

``geometry``
    Mass properties and the dimensionless groups (memo 2.2, 3.0; Fig. 1-2).
``beam``
    The equivalent free-free beam: lambda_n, alpha_n, mode shapes, omega_1 (4.1, appendix C).
``pitch``
    Rigid-body pitch: Mathieu a, q (4.2-4), the exponent beta, psi(tau) (4.2-6..9).
``beam_action``
    The gimbaled beam under the pulsating follower thrust: exponents alpha_r (4.1, ref. 11).
``shell_coefficients``, ``shell``
    Galerkin coefficients (appendix A) and shell natural frequencies (5.4, 6.2, appendix D).
``stability``
    The 13 families of stability equations of memo 7.3 and their roots.
``responses``
    Modal time responses (6.1, 6.2), split by concern.

Every function is pure over SI floats and numpy arrays; nothing here imports the input layer or
the presentation layer.
"""

__all__: list[str] = []
