"""What test_pickle.py runs in a process started with multiprocessing's 'spawn' context: a fresh
interpreter that receives a pickled scene and sends back its answers."""

import pickle


def cast_in_child(payload, rays):
    scene = pickle.loads(payload)
    hits = scene.cast_rays(rays)
    return {key: value.tobytes() for key, value in hits.items()}, scene.geometry_count()
