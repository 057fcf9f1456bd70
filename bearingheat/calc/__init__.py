"""Forward orchestration over tables of supports: the column contract, the friction-model registry,
the support arrays and the extensions (heat balance, ball contact, plain bushings)."""
