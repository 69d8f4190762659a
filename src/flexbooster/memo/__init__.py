"""The memo's method (Tech Memo 104), stage by stage, in numpy and scipy only: ``geometry``
(2.2, 3.0), ``beam`` (4.1, appendix C), ``pitch`` (4.2), ``beam_action`` (4.1, ref. 11),
``shell_coefficients`` and ``shell`` (5.4, 6.2, appendices A, D), ``stability`` (7.3),
``severity`` (7.1) and ``responses`` (6.1, 6.2).
"""

__all__: list[str] = []
