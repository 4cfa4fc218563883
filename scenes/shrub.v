angle increment: 22.5
initial line width: 0.2
