#!/bin/bash
echo "hello from the fixture"
