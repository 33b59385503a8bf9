#!/usr/bin/env python3
"""Checks that includes point only downwards between the layers (docs/architecture.md) and that no
source or header grows past the size a reader can hold.

    python3 scripts/check_layers.py [ROOT]      (ROOT: the checkout, default: this script's parent)

Prints every offending include as FILE:LINE: LAYER includes LAYER (HEADER) and every file over
MAX_LINES lines; exits 1 when there is one, 0 otherwise."""
import os
import re
import sys

MAX_LINES = 450

# What each layer may include (besides itself). The core is private: only the segmentation
# sources reach it, never a public header.
ALLOWED = {
    'common': set(),
    'core': {'common'},
    'io': {'common'},
    'segmentation': {'common', 'core'},
    'signature': {'common', 'segmentation', 'io'},
    'evaluation': {'common', 'segmentation', 'io', 'signature'},
    # The Python module (python/src) binds the public library, never the core or the evaluation.
    'python': {'common', 'segmentation', 'io', 'signature'},
}
PUBLIC_MAY_NOT = {'core'}

# Inside the core (src/core/STEP/): what each step of the pipeline may include besides itself.
CORE_ALLOWED = {
    'support': set(),
    'geometry': {'support'},
    'delaunay': {'support'},
    'preparation': {'support', 'geometry'},
    'flow': {'support', 'geometry', 'delaunay'},
    'interior': {'support', 'geometry', 'delaunay'},
    'labels': {'support', 'geometry'},
    'merging': {'support', 'geometry', 'flow'},
}

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')


def layer_of_file(relative):
    """The layer a project file belongs to, or None outside src/, include/ and python/src/."""
    parts = relative.split(os.sep)
    if parts[0] == 'include' and len(parts) > 2 and parts[1] == 'pcl_flowseg':
        return parts[2] if parts[2] in ALLOWED else '?'
    if parts[0] == 'src' and len(parts) > 1:
        return parts[1] if parts[1] in ALLOWED else '?'
    if parts[:2] == ['python', 'src']:
        return 'python'
    return None


def layer_of_include(header):
    """The layer an included project header belongs to, or None for third-party headers."""
    parts = header.split('/')
    if parts[0] == 'pcl_flowseg' and len(parts) > 2:
        return parts[1]
    if parts[0] in ALLOWED and len(parts) > 1:  # "core/...", "io/..." relative to src/
        return parts[0]
    return None


def check_core_step(relative, header):
    """Why an include between two steps of the core points the wrong way, or None."""
    source = relative.split(os.sep)[2] if relative.count(os.sep) >= 3 else '?'
    target = header.split('/')[1] if header.count('/') >= 2 else '?'
    if source not in CORE_ALLOWED or target not in CORE_ALLOWED:
        return 'core step %s or %s is not in CORE_ALLOWED' % (source, target)
    if target != source and target not in CORE_ALLOWED[source]:
        return 'core/%s includes core/%s (%s)' % (source, target, header)
    return None


def check(root):
    problems = []
    for top in ('src', 'include', os.path.join('python', 'src')):
        for folder, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith(('.h', '.hpp', '.cpp')):
                    continue
                path = os.path.join(folder, name)
                relative = os.path.relpath(path, root)
                layer = layer_of_file(relative)
                lines = open(path, encoding='utf-8', errors='replace').read().split('\n')
                if len(lines) > MAX_LINES:
                    problems.append('%s: %d lines (at most %d)' % (relative, len(lines), MAX_LINES))
                if layer == '?':
                    problems.append('%s: in no layer of docs/architecture.md' % relative)
                    continue
                for number, line in enumerate(lines, 1):
                    match = INCLUDE.match(line)
                    target = layer_of_include(match.group(1)) if match else None
                    if target == 'core' and layer == 'core':
                        problem = check_core_step(relative, match.group(1))
                        if problem:
                            problems.append('%s:%d: %s' % (relative, number, problem))
                        continue
                    if target is None or target == layer:
                        continue
                    public = relative.startswith('include')
                    if target not in ALLOWED[layer] or (public and target in PUBLIC_MAY_NOT):
                        problems.append('%s:%d: %s includes %s (%s)' % (relative, number, layer, target, match.group(1)))
    return problems


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
    if not os.path.isdir(os.path.join(root, 'src')):
        print('check_layers: no src/ under %s' % root, file=sys.stderr)
        return 2
    problems = check(root)
    for p in problems:
        print(p)
    print('check_layers: %d problem(s)' % len(problems))
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
