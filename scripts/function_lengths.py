#!/usr/bin/env python3
"""Lists the longest function bodies of the C++ sources: python3 scripts/function_lengths.py [N (10)] [DIR...]
(default src include apps). A body is counted from its opening brace on a line of its own (after a
signature that ends with ')' or ') const', possibly with an initialiser list) to the matching close."""
import os
import re
import sys

count = int(sys.argv[1]) if len(sys.argv) > 1 and sys.argv[1].isdigit() else 10
roots = [a for a in sys.argv[1:] if not a.isdigit()] or ['src', 'include', 'apps']
signature_end = re.compile(r'\)\s*(const)?\s*(noexcept)?\s*(override)?\s*$|^\s*:\s*\w+ \(|^\s*,?\s*\w+_ \(')
control = re.compile(r'^\s*(if|for|while|switch|else|do|try|catch)\b|\b(if|for|while|switch)\s*\(')
rows = []
for root in roots:
    for folder, _, files in os.walk(root):
        for name in files:
            if not name.endswith(('.cpp', '.h', '.hpp')):
                continue
            path = os.path.join(folder, name)
            lines = open(path, encoding='utf-8', errors='replace').read().split('\n')
            for i, line in enumerate(lines):
                if line.strip() != '{' or i == 0:
                    continue
                before = lines[i - 1]
                if not signature_end.search(before) or control.search(before) or before.strip().startswith(('*', '/')):
                    continue
                j = i - 1
                while j > 0 and '(' not in lines[j] and i - j < 8:
                    j -= 1
                depth, k = 0, i
                while k < len(lines):
                    depth += lines[k].count('{') - lines[k].count('}')
                    if depth <= 0:
                        break
                    k += 1
                rows.append((k - i + 1, path, j + 1, re.sub(r'\s+', ' ', lines[j].strip())[:80]))
rows.sort(key=lambda r: -r[0])
for length, path, line, signature in rows[:count]:
    print(f"{length:5d}  {path}:{line}  {signature}")
