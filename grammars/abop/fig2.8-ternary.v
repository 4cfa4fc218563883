angle increment: 45
initial line width: 1
tropism: T: 0 -1 0 E: 0.22
