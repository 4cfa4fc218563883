// Derives one of the peer grammars with the `lindenmayer` npm package and prints {"modules", "seconds"} as JSON
// (or the string with --string). Usage: node derive.js abop-1.24d|abop-1.31a STEPS [--string]
'use strict';
const path = require('path');
const LSystem = require(path.join(__dirname, 'node_modules', 'lindenmayer'));

// The same grammars as grammars/abop/fig1.24d.l and fig1.31a.l.
const grammars = {
  'abop-1.24d': () => new LSystem({
    axiom: 'X',
    productions: { X: 'F[+X]F[-X]+X', F: 'FF' },
  }),
  'abop-1.31a': () => new LSystem({
    axiom: 'F1F1F1',
    ignoredSymbols: '+-F',
    productions: {
      '0<0>0': '0',
      '0<0>1': '1[+F1F1]',
      '0<1>0': '1',
      '0<1>1': '1',
      '1<0>0': '0',
      '1<0>1': '1F1',
      '1<1>0': '0',
      '1<1>1': '0',
      '+': '-',
      '-': '+',
    },
  }),
};

const [name, stepsText, flag] = process.argv.slice(2);
if (!grammars[name] || !/^\d+$/.test(stepsText || '')) {
  console.error(`usage: node derive.js ${Object.keys(grammars).join('|')} STEPS [--string]`);
  process.exit(2);
}
const system = grammars[name]();
const start = process.hrtime.bigint();
const result = system.iterate(Number(stepsText));
const seconds = Number(process.hrtime.bigint() - start) * 1e-9;
if (flag === '--string') {
  console.log(result);
} else {
  console.log(JSON.stringify({ modules: result.length, seconds }));
}
