angle increment: 25.75
initial line width: 1
