# MSMS solvent excluded surface vertices
#vertex #sphere density probe_r
      3       0  1.00  1.40
    0.000     0.000     0.000     0.000     0.000     1.000       0       0  1
    1.000     0.000     0.000     0.000     0.000     1.000       0       0  1
    0.000     1.000     0.000     0.000     0.000     1.000       0       0  1
