angle increment: 25.7
initial line width: 1
